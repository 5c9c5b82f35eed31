// The compressed writers' streams (io/src/zlib_stream.hpp) read back by zlib itself and by a plain
// base64 decoder: RFC 4648's test vectors, data fed in pieces of every length, both contents.
#include "zlib_stream.hpp"

#include "temp_path.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace semimesh::io {
namespace {

std::string temporary_path(const std::string& name) { return semimesh::test::temp_path(name).string(); }

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// `data` through Base64Out, fed in pieces of the given lengths in turn.
std::string base64(const std::string& data, const std::vector<std::size_t>& pieces) {
  const std::string path = temporary_path("base64");
  {
    AtomicFile file(path);
    Base64Out out(file);
    std::size_t at = 0, k = 0;
    while (at < data.size()) {
      const std::size_t take = std::min(pieces[k++ % pieces.size()], data.size() - at);
      out.add(data.data() + at, take);
      at += take;
    }
    out.finish();
    file.commit();
  }
  std::string text = read_file(path);
  std::remove(path.c_str());
  return text;
}

/// The obvious decoder of padded base64 (RFC 4648, section 4).
std::string decode_base64(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned bits = 0, count = 0;
  for (char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<unsigned>(alphabet.find(c));
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<char>((bits >> count) & 0xff));
    }
  }
  return out;
}

std::string random_bytes(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::string s(n, '\0');
  for (char& c : s) c = static_cast<char>(rng() & 0xff);
  return s;
}

TEST(Base64Out, EncodesTheRfcTestVectors) {
  const std::pair<const char*, const char*> vectors[] = {{"", ""},         {"f", "Zg=="},         {"fo", "Zm8="},
                                                         {"foo", "Zm9v"},  {"foob", "Zm9vYg=="},  {"fooba", "Zm9vYmE="},
                                                         {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : vectors) {
    EXPECT_EQ(base64(plain, {1}), encoded) << plain;
    EXPECT_EQ(base64(plain, {100}), encoded) << plain;
  }
}

// More than the encoder's 64 KiB buffer, fed in pieces that leave every carry (0, 1, 2 bytes).
TEST(Base64Out, AnyPiecesGiveTheWholeDataBack) {
  const std::string data = random_bytes(200001, 3);
  const std::string whole = base64(data, {data.size()});
  EXPECT_EQ(whole.size(), 4 * ((data.size() + 2) / 3));
  EXPECT_EQ(decode_base64(whole), data);
  for (const std::vector<std::size_t>& pieces :
       std::vector<std::vector<std::size_t>>{{1}, {2}, {7, 1, 5}, {65536, 4}, {3 * 21845 + 2}}) {
    EXPECT_EQ(base64(data, pieces), whole);
  }
}

// Integers (deflated) and doubles (stored blocks) over several of the stream's 1 MiB chunks: one
// zlib stream that zlib's own inflate reads back whole, checksum included.
TEST(ZlibStream, ZlibInflatesEitherContentBackWhole) {
  std::vector<std::int64_t> ids(400000);
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<std::int64_t>(i / 3);
  std::vector<double> points(400000);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = std::sin(0.001 * static_cast<double>(i));
  const std::pair<Content, std::string> cases[] = {
      {Content::Integers, std::string(reinterpret_cast<const char*>(ids.data()), ids.size() * sizeof(std::int64_t))},
      {Content::Doubles, std::string(reinterpret_cast<const char*>(points.data()), points.size() * sizeof(double))}};
  for (const auto& [content, raw] : cases) {
    std::string compressed;
    {
      ZlibStream z([&](const char* data, std::size_t bytes) { compressed.append(data, bytes); }, content);
      for (std::size_t at = 0; at < raw.size(); at += 100003) z.add(raw.data() + at, std::min<std::size_t>(100003, raw.size() - at));
      z.finish();
    }
    std::string back(raw.size(), '\0');
    uLongf length = static_cast<uLongf>(back.size());
    ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(back.data()), &length,
                         reinterpret_cast<const Bytef*>(compressed.data()), static_cast<uLong>(compressed.size())),
              Z_OK);
    EXPECT_EQ(length, raw.size());
    EXPECT_TRUE(back == raw);
    if (content == Content::Integers) {
      EXPECT_LT(compressed.size(), raw.size() / 4);  // deflated
    } else {
      EXPECT_GT(compressed.size(), raw.size());  // stored
    }
  }
}

// VTK's blocks: each its own zlib stream, read back by zlib.
TEST(ZlibStream, EachBlockIsAZlibStreamOfItsOwn) {
  std::vector<std::string> blocks{random_bytes(65536, 1), std::string(65536, 'a'), random_bytes(1000, 2), ""};
  for (Content content : {Content::Integers, Content::Doubles}) {
    const std::vector<std::string> compressed = zlib_compress_blocks(blocks, content);
    ASSERT_EQ(compressed.size(), blocks.size());
    for (std::size_t k = 0; k < blocks.size(); ++k) {
      std::string back(blocks[k].size() + 1, '\0');
      uLongf length = static_cast<uLongf>(back.size());
      ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(back.data()), &length,
                           reinterpret_cast<const Bytef*>(compressed[k].data()), static_cast<uLong>(compressed[k].size())),
                Z_OK);
      back.resize(length);
      EXPECT_TRUE(back == blocks[k]) << "block " << k;
    }
  }
}

}  // namespace
}  // namespace semimesh::io
