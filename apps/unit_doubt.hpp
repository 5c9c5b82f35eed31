// Whether a CAD file's declared length unit fits its wing: files often carry their tool's default
// unit (an IGES header saying INCH) on numbers in another (metres). A wing's root chord lies
// between 5 cm (a small wind-tunnel model) and 100 m; a declared unit that puts the chord outside
// is doubted, and the known unit that puts it nearest the middle of that range (in ratio) offered.
#pragma once

#include <optional>
#include <string>

namespace semimesh::app {

struct UnitDoubt {
  std::string likelier;  ///< the unit label to write as geometry.units
  std::string why;       ///< one sentence naming the chord in both units
};

/// `chord`: the root chord in the model's numbers; `unit`: their declared label (mm, cm, m, km,
/// um, in, ft). Nothing when the unit is not a length unit (a generated wing's "chord") or fits.
std::optional<UnitDoubt> doubt_unit(double chord, const std::string& unit);

}  // namespace semimesh::app
