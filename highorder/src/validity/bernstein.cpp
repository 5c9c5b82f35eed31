#include "semimesh/ho/bernstein.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace semimesh::ho {
namespace {

double factorial(int n) {
  double result = 1.0;
  for (int k = 2; k <= n; ++k) result *= k;
  return result;
}

double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  return std::round(factorial(n) / (factorial(k) * factorial(n - k)));
}

std::shared_ptr<const BernsteinLayout> build_layout(const std::vector<SimplexFactor>& factors) {
  auto layout = std::make_shared<BernsteinLayout>();
  layout->factors = factors;
  std::array<int, 3> extent{1, 1, 1};
  int var = 0;
  for (int f = 0; f < static_cast<int>(factors.size()); ++f) {
    if (factors[f].dim < 1 || factors[f].degree < 0)
      throw std::invalid_argument("Bernstein layout: factor " + std::to_string(f) +
                                  " needs dim >= 1 and degree >= 0");
    for (int slot = 1; slot <= factors[f].dim; ++slot) {
      if (var >= 3) throw std::invalid_argument("Bernstein layout: more than 3 variables");
      layout->var_factor[var] = f;
      layout->var_slot[var] = slot;
      extent[var] = factors[f].degree + 1;
      ++var;
    }
  }
  layout->num_vars = var;
  layout->box_stride = {1, extent[0], extent[0] * extent[1]};
  layout->box_to_id.assign(extent[0] * extent[1] * extent[2], -1);
  for (int i2 = 0; i2 < extent[2]; ++i2)
    for (int i1 = 0; i1 < extent[1]; ++i1)
      for (int i0 = 0; i0 < extent[0]; ++i0) {
        const std::array<int, 3> free{i0, i1, i2};
        std::vector<int> factor_sum(factors.size(), 0);
        for (int v = 0; v < layout->num_vars; ++v) factor_sum[layout->var_factor[v]] += free[v];
        bool inside = true;
        double weight = 1.0;
        for (std::size_t f = 0; f < factors.size(); ++f) {
          if (factor_sum[f] > factors[f].degree) inside = false;
          else weight *= factorial(factors[f].degree) / factorial(factors[f].degree - factor_sum[f]);
        }
        if (!inside) continue;
        for (int v = 0; v < layout->num_vars; ++v) weight /= factorial(free[v]);
        layout->box_to_id[i0 + extent[0] * (i1 + extent[1] * i2)] = layout->size();
        layout->index.push_back(free);
        layout->multinomial.push_back(std::round(weight));
      }
  // A corner: in every factor at most one free component is non-zero and it equals the degree, or
  // all are zero (vertex 0).
  for (int id = 0; id < layout->size(); ++id) {
    bool corner = true;
    for (std::size_t f = 0; f < factors.size(); ++f)
      for (int slot = 0; slot <= factors[f].dim; ++slot) {
        const int a = layout->component(id, static_cast<int>(f), slot);
        if (a != 0 && a != factors[f].degree) corner = false;
      }
    if (corner) layout->corners.push_back(id);
  }
  return layout;
}

}  // namespace

int BernsteinLayout::id_of(const std::array<int, 3>& free_components) const {
  int offset = 0;
  for (int v = 0; v < 3; ++v) {
    const int extent = v < num_vars ? factors[var_factor[v]].degree + 1 : 1;
    if (free_components[v] < 0 || free_components[v] >= extent) return -1;
    offset += free_components[v] * box_stride[v];
  }
  return box_to_id[offset];
}

int BernsteinLayout::component(int id, int factor, int slot) const {
  int sum = 0;
  for (int v = 0; v < num_vars; ++v) {
    if (var_factor[v] != factor) continue;
    if (var_slot[v] == slot) return index[id][v];
    sum += index[id][v];
  }
  return factors[factor].degree - sum;  // slot 0: the implicit component
}

std::shared_ptr<const BernsteinLayout> BernsteinLayout::get(const std::vector<SimplexFactor>& factors) {
  static std::mutex mutex;
  static std::map<std::vector<std::pair<int, int>>, std::shared_ptr<const BernsteinLayout>> cache;
  std::vector<std::pair<int, int>> key;
  for (const SimplexFactor& f : factors) key.emplace_back(f.dim, f.degree);
  std::lock_guard<std::mutex> lock(mutex);
  auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  auto layout = build_layout(factors);
  cache.emplace(std::move(key), layout);
  return layout;
}

BernsteinPolynomial::BernsteinPolynomial(const std::vector<SimplexFactor>& factors)
    : BernsteinPolynomial(BernsteinLayout::get(factors)) {}

BernsteinPolynomial::BernsteinPolynomial(std::shared_ptr<const BernsteinLayout> layout)
    : layout_(std::move(layout)), coefficients_(Eigen::VectorXd::Zero(layout_->size())) {}

Eigen::VectorXd BernsteinPolynomial::basis_values(const BernsteinLayout& layout, const Eigen::Vector3d& point) {
  // Barycentric coordinates per factor: lambda_0 = 1 - sum of its variables.
  std::vector<std::array<double, 4>> lambda(layout.factors.size(), {1.0, 0.0, 0.0, 0.0});
  for (int v = 0; v < layout.num_vars; ++v) {
    lambda[layout.var_factor[v]][layout.var_slot[v]] = point[v];
    lambda[layout.var_factor[v]][0] -= point[v];
  }
  Eigen::VectorXd values(layout.size());
  for (int id = 0; id < layout.size(); ++id) {
    double value = layout.multinomial[id];
    for (std::size_t f = 0; f < layout.factors.size(); ++f)
      for (int slot = 0; slot <= layout.factors[f].dim; ++slot) {
        const int power = layout.component(id, static_cast<int>(f), slot);
        if (power > 0) value *= std::pow(lambda[f][slot], power);
      }
    values[id] = value;
  }
  return values;
}

double BernsteinPolynomial::evaluate(const Eigen::Vector3d& point) const {
  return basis_values(*layout_, point).dot(coefficients_);
}

BernsteinPolynomial BernsteinPolynomial::derivative(int var) const {
  if (var < 0 || var >= layout_->num_vars)
    throw std::invalid_argument("Bernstein derivative: variable " + std::to_string(var) + " out of range");
  const int factor = layout_->var_factor[var];
  const int degree = layout_->factors[factor].degree;
  std::vector<SimplexFactor> factors = layout_->factors;
  factors[factor].degree = std::max(0, degree - 1);
  BernsteinPolynomial result(factors);
  if (degree == 0) return result;  // derivative of a constant
  const BernsteinLayout& out = result.layout();
  for (int id = 0; id < out.size(); ++id) {
    std::array<int, 3> up = out.index[id];
    const int base = layout_->id_of(up);
    ++up[var];
    result.coefficients_[id] = degree * (coefficients_[layout_->id_of(up)] - coefficients_[base]);
  }
  return result;
}

BernsteinPolynomial BernsteinPolynomial::divide_by_one_minus(int var) const {
  const int factor = layout_->var_factor[var];
  const int degree = layout_->factors[factor].degree;
  if (layout_->factors[factor].dim != 1 || degree < 1)
    throw std::invalid_argument("Bernstein division by (1 - t): variable " + std::to_string(var) +
                                " must be a segment factor of degree >= 1");
  std::vector<SimplexFactor> factors = layout_->factors;
  factors[factor].degree = degree - 1;
  BernsteinPolynomial result(factors);
  const BernsteinLayout& out = result.layout();
  for (int id = 0; id < out.size(); ++id) {
    const int s = out.index[id][var];
    result.coefficients_[id] = coefficients_[layout_->id_of(out.index[id])] * degree / (degree - s);
  }
  return result;
}

namespace {

/// The layout of a product of two polynomials of these layouts (degrees add factor by factor).
std::vector<SimplexFactor> product_layout_factors(const BernsteinLayout& la, const BernsteinLayout& lb) {
  if (la.factors.size() != lb.factors.size())
    throw std::invalid_argument("Bernstein product: operands have different factor structures");
  std::vector<SimplexFactor> factors = la.factors;
  for (std::size_t f = 0; f < factors.size(); ++f) {
    if (la.factors[f].dim != lb.factors[f].dim)
      throw std::invalid_argument("Bernstein product: operands have different factor dimensions");
    factors[f].degree += lb.factors[f].degree;
  }
  return factors;
}

/// [size] place of each coefficient of `in` in the dense box of `out`.
std::vector<int> box_offsets(const BernsteinLayout& in, const BernsteinLayout& out) {
  std::vector<int> offset(in.size(), 0);
  for (int i = 0; i < in.size(); ++i)
    for (int v = 0; v < in.num_vars; ++v) offset[i] += in.index[i][v] * out.box_stride[v];
  return offset;
}

/// The result's coefficients from its scaled coefficients accumulated in its dense box.
void gather_box(const std::vector<double>& box, BernsteinPolynomial& result) {
  const BernsteinLayout& out = result.layout();
  for (int k = 0; k < out.size(); ++k) {
    const std::array<int, 3>& free = out.index[k];
    const double scaled = box[free[0] * out.box_stride[0] + free[1] * out.box_stride[1] + free[2] * out.box_stride[2]];
    result.coefficients()[k] = scaled / out.multinomial[k];
  }
}

using BoxRun = ScaledProduct::BoxRun;

std::vector<BoxRun> box_runs(const std::vector<int>& offset) {
  std::vector<BoxRun> runs;
  for (int j = 0; j < static_cast<int>(offset.size()); ++j) {
    if (!runs.empty() && offset[j] == runs.back().offset + runs.back().length && runs.back().first + runs.back().length == j)
      ++runs.back().length;
    else
      runs.push_back({j, offset[j], 1});
  }
  return runs;
}

/// box[offset + run.offset + t] += scale * source[run.first + t] over every run: kLength > 0 when
/// all runs have that length (a fixed inner loop the compiler unrolls; the runs of a hexahedron's
/// and a prism's segment are all equally long), 0 for runs of any length.
template <int kLength>
void accumulate_runs(const std::vector<BoxRun>& runs, const double* __restrict source, double scale,
                     double* __restrict box) {
  for (const BoxRun& run : runs) {
    double* target = box + run.offset;
    const double* from = source + run.first;
    const int length = kLength > 0 ? kLength : run.length;
    for (int t = 0; t < length; ++t) target[t] += scale * from[t];
  }
}

using RunAccumulator = ScaledProduct::RunAccumulator;
using RunGroup = ScaledProduct::RunGroup;

/// The accumulate_runs for these runs: fixed lengths 1..kMaxFixedRun, else any length.
constexpr int kMaxFixedRun = 16;
template <int... kLengths>
RunAccumulator pick_accumulator(int length, std::integer_sequence<int, kLengths...>) {
  constexpr RunAccumulator fixed[] = {&accumulate_runs<kLengths + 1>...};
  return length >= 1 && length <= kMaxFixedRun ? fixed[length - 1] : &accumulate_runs<0>;
}

/// The runs grouped by length, each group with its accumulate_runs (in order of first appearance).
std::vector<RunGroup> run_groups(const std::vector<BoxRun>& runs) {
  std::vector<RunGroup> groups;
  std::vector<int> lengths;  // [groups]
  for (const BoxRun& run : runs) {
    auto at = std::find(lengths.begin(), lengths.end(), run.length);
    if (at == lengths.end()) {
      groups.push_back({{}, pick_accumulator(run.length, std::make_integer_sequence<int, kMaxFixedRun>{})});
      at = lengths.insert(lengths.end(), run.length);
    }
    groups[static_cast<std::size_t>(at - lengths.begin())].runs.push_back(run);
  }
  return groups;
}

/// The product of two layouts (cached per pair of layouts, which live as long as the program).
const ScaledProduct& product_of(const BernsteinLayout& la, const BernsteinLayout& lb) {
  thread_local std::map<std::pair<const BernsteinLayout*, const BernsteinLayout*>, ScaledProduct> plans;
  const auto key = std::make_pair(&la, &lb);
  auto it = plans.find(key);
  if (it == plans.end()) it = plans.emplace(key, ScaledProduct(la, lb)).first;
  return it->second;
}

}  // namespace

ScaledProduct::ScaledProduct(const BernsteinLayout& a, const BernsteinLayout& b)
    : out_(BernsteinLayout::get(product_layout_factors(a, b))),
      offset_a_(box_offsets(a, *out_)),
      groups_b_(run_groups(box_runs(box_offsets(b, *out_)))),
      places_(box_offsets(*out_, *out_)) {}

void ScaledProduct::gather(const double* box, double* out) const {
  for (std::size_t k = 0; k < places_.size(); ++k) out[k] = box[places_[k]];
}

void ScaledProduct::accumulate(const double* a, const double* b, double factor, double* box) const {
  for (std::size_t i = 0; i < offset_a_.size(); ++i) {
    const double scaled_a = factor * a[i];
    if (scaled_a == 0.0) continue;
    for (const RunGroup& group : groups_b_) group.accumulate(group.runs, b, scaled_a, box + offset_a_[i]);
  }
}

// In the scaled basis (multinomial folded into the coefficient) the product is a plain convolution
// of multi-indices: alpha + beta, accumulated in the dense box of the result, then gathered.
// Each box entry receives its terms in the order of a's coefficients, as in multiply_pairwise, so
// the two give the same bits; here b's coefficients go in runs that are contiguous in the box (a
// line along the first variable), an inner loop the compiler vectorises, with no per-call buffers.
BernsteinPolynomial operator*(const BernsteinPolynomial& a, const BernsteinPolynomial& b) {
  const BernsteinLayout& la = a.layout();
  const BernsteinLayout& lb = b.layout();
  const ScaledProduct& product = product_of(la, lb);
  BernsteinPolynomial result(product.out());
  const BernsteinLayout& out = result.layout();
  thread_local std::vector<double> scaled_a, scaled_b, box;
  scaled_a.resize(la.size());
  scaled_b.resize(lb.size());
  for (int i = 0; i < la.size(); ++i) scaled_a[i] = a.coefficients()[i] * la.multinomial[i];
  for (int j = 0; j < lb.size(); ++j) scaled_b[j] = b.coefficients()[j] * lb.multinomial[j];
  box.assign(out.box_to_id.size(), 0.0);
  product.accumulate(scaled_a.data(), scaled_b.data(), 1.0, box.data());
  gather_box(box, result);
  return result;
}

BernsteinPolynomial multiply_pairwise(const BernsteinPolynomial& a, const BernsteinPolynomial& b) {
  const BernsteinLayout& la = a.layout();
  const BernsteinLayout& lb = b.layout();
  BernsteinPolynomial result(product_layout_factors(la, lb));
  const BernsteinLayout& out = result.layout();
  const std::vector<int> offset_a = box_offsets(la, out), offset_b = box_offsets(lb, out);
  std::vector<double> box(out.box_to_id.size(), 0.0);
  for (int i = 0; i < la.size(); ++i) {
    const double scaled_a = a.coefficients()[i] * la.multinomial[i];
    if (scaled_a == 0.0) continue;
    for (int j = 0; j < lb.size(); ++j) box[offset_a[i] + offset_b[j]] += scaled_a * (b.coefficients()[j] * lb.multinomial[j]);
  }
  gather_box(box, result);
  return result;
}

BernsteinPolynomial operator+(BernsteinPolynomial a, const BernsteinPolynomial& b) {
  if (a.layout_ != b.layout_) throw std::invalid_argument("Bernstein sum: operands have different layouts");
  a.coefficients_ += b.coefficients_;
  return a;
}

BernsteinPolynomial operator-(BernsteinPolynomial a, const BernsteinPolynomial& b) {
  if (a.layout_ != b.layout_) throw std::invalid_argument("Bernstein difference: operands have different layouts");
  a.coefficients_ -= b.coefficients_;
  return a;
}

BernsteinPolynomial& BernsteinPolynomial::operator*=(double scale) {
  coefficients_ *= scale;
  return *this;
}

void BernsteinPolynomial::bisect(int factor, int vertex_a, int vertex_b, BernsteinPolynomial& first,
                                 BernsteinPolynomial& second) const {
  const BernsteinLayout& l = *layout_;
  const int dim = l.factors.at(factor).dim;
  if (vertex_a == vertex_b || vertex_a < 0 || vertex_b < 0 || vertex_a > dim || vertex_b > dim)
    throw std::invalid_argument("Bernstein bisection: invalid edge of factor " + std::to_string(factor));
  // The variables holding alpha_a and alpha_b (-1: the implicit component alpha_0).
  int var_a = -1, var_b = -1;
  for (int v = 0; v < l.num_vars; ++v) {
    if (l.var_factor[v] != factor) continue;
    if (l.var_slot[v] == vertex_a) var_a = v;
    if (l.var_slot[v] == vertex_b) var_b = v;
  }
  first = BernsteinPolynomial(layout_);
  second = BernsteinPolynomial(layout_);
  std::vector<int> line;
  std::vector<double> work;
  for (int start = 0; start < l.size(); ++start) {
    if (l.component(start, factor, vertex_b) != 0) continue;  // each line starts at alpha_b = 0
    const int k = l.component(start, factor, vertex_a);
    // Coefficients along the line alpha_a = k - m, alpha_b = m, m = 0..k.
    line.assign(k + 1, -1);
    for (int m = 0; m <= k; ++m) {
      std::array<int, 3> free = l.index[start];
      if (var_a >= 0) free[var_a] = k - m;
      if (var_b >= 0) free[var_b] = m;
      line[m] = l.id_of(free);
    }
    work.resize(k + 1);
    for (int m = 0; m <= k; ++m) work[m] = coefficients_[line[m]];
    first.coefficients_[line[0]] = work[0];
    second.coefficients_[line[k]] = work[k];
    for (int level = 1; level <= k; ++level) {
      for (int q = 0; q + level <= k; ++q) work[q] = 0.5 * (work[q] + work[q + 1]);
      first.coefficients_[line[level]] = work[0];
      second.coefficients_[line[k - level]] = work[k - level];
    }
  }
}

namespace {

/// The coefficient ids along each line of variable `var` of a layout, [lines][degree + 1], alpha_var
/// = 0..degree (cached per layout and variable, which live as long as the program).
const std::vector<int>& lines_of(const BernsteinLayout& l, int var) {
  thread_local std::map<std::pair<const BernsteinLayout*, int>, std::vector<int>> cache;
  std::vector<int>& lines = cache[{&l, var}];
  if (!lines.empty() || l.size() == 0) return lines;
  const int n = l.factors[l.var_factor[var]].degree;
  for (int start = 0; start < l.size(); ++start) {
    if (l.index[start][var] != 0) continue;  // each line starts at alpha_var = 0
    for (int m = 0; m <= n; ++m) {
      std::array<int, 3> free = l.index[start];
      free[var] = m;
      lines.push_back(l.id_of(free));
    }
  }
  return lines;
}

/// restricted()'s step along one line: the degree-n coefficients `c` [n + 1] of the line on [0, 1]
/// become those of its part [a, b], in `out` [n + 1]. 1D de Casteljau at b keeping [0, b], then at
/// a / b keeping the rest.
void restrict_line(const double* c, int n, double a, double b, double* out) {
  thread_local std::vector<double> work, left;
  work.assign(c, c + n + 1), left.resize(n + 1);
  // [0, b]: the first entry of each de Casteljau level at b.
  left[0] = work[0];
  for (int level = 1; level <= n; ++level) {
    for (int q = 0; q + level <= n; ++q) work[q] = (1.0 - b) * work[q] + b * work[q + 1];
    left[level] = work[0];
  }
  // [a, b] = [s, 1] of [0, b]: the last entry of each level at s.
  const double s = a / b;
  out[n] = left[n];
  for (int level = 1; level <= n; ++level) {
    for (int q = 0; q + level <= n; ++q) left[q] = (1.0 - s) * left[q] + s * left[q + 1];
    out[n - level] = left[n - level];
  }
}

/// The matrix of restrict_line on [a, b] at degree n, (n + 1, n + 1): column j is the restriction
/// of the j-th basis polynomial's coefficients (the unit vector e_j). Kept per thread: the layers of
/// a stack cut every element at the same interfaces, so a few intervals recur (making one is
/// (n + 1)^3 operations, applying it (n + 1)^2 per line). The cache is emptied when it grows past
/// kKeptMatrices (callers whose intervals never recur).
const Eigen::MatrixXd& restriction_matrix(int n, double a, double b) {
  constexpr std::size_t kKeptMatrices = 1024;
  thread_local std::map<std::tuple<int, double, double>, Eigen::MatrixXd> kept;
  const auto key = std::make_tuple(n, a, b);
  if (const auto it = kept.find(key); it != kept.end()) return it->second;
  if (kept.size() >= kKeptMatrices) kept.clear();
  Eigen::MatrixXd r(n + 1, n + 1);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n + 1);
  for (int j = 0; j <= n; ++j) {
    unit[j] = 1.0;
    restrict_line(unit.data(), n, a, b, r.col(j).data());
    unit[j] = 0.0;
  }
  return kept.emplace(key, std::move(r)).first->second;
}

}  // namespace

void BernsteinPolynomial::check_restriction(int var, double a, double b) const {
  const BernsteinLayout& l = *layout_;
  if (var < 0 || var >= l.num_vars || l.factors[l.var_factor[var]].dim != 1)
    throw std::invalid_argument("Bernstein restriction: variable " + std::to_string(var) + " is not a segment's");
  if (!(0.0 <= a && a < b && b <= 1.0))
    throw std::invalid_argument("Bernstein restriction: [" + std::to_string(a) + ", " + std::to_string(b) +
                                "] is not an interval inside [0, 1]");
}

BernsteinPolynomial BernsteinPolynomial::restricted(int var, double a, double b) const {
  check_restriction(var, a, b);
  const BernsteinLayout& l = *layout_;
  const int n = l.factors[l.var_factor[var]].degree;
  BernsteinPolynomial out(layout_);
  const std::vector<int>& lines = lines_of(l, var);
  std::vector<double> in_line(n + 1), out_line(n + 1);
  for (std::size_t first = 0; first < lines.size(); first += n + 1) {
    const int* line = &lines[first];
    for (int m = 0; m <= n; ++m) in_line[m] = coefficients_[line[m]];
    restrict_line(in_line.data(), n, a, b, out_line.data());
    for (int m = 0; m <= n; ++m) out.coefficients_[line[m]] = out_line[m];
  }
  return out;
}

std::vector<BernsteinPolynomial> BernsteinPolynomial::restricted_to_each(
    int var, const std::vector<std::array<double, 2>>& intervals) const {
  for (const auto& [a, b] : intervals) check_restriction(var, a, b);
  if (intervals.empty()) return {};
  const BernsteinLayout& l = *layout_;
  const int n = l.factors[l.var_factor[var]].degree;
  const std::vector<int>& lines = lines_of(l, var);
  const Eigen::Index num_lines = static_cast<Eigen::Index>(lines.size()) / (n + 1);
  // Column k: line k's coefficients, alpha_var = 0..n.
  Eigen::MatrixXd along(n + 1, num_lines), part(n + 1, num_lines);
  for (Eigen::Index k = 0; k < num_lines; ++k)
    for (int m = 0; m <= n; ++m) along(m, k) = coefficients_[lines[k * (n + 1) + m]];
  std::vector<BernsteinPolynomial> out;
  out.reserve(intervals.size());
  for (const auto& [a, b] : intervals) {
    part.noalias() = restriction_matrix(n, a, b) * along;
    out.emplace_back(layout_);
    Eigen::VectorXd& c = out.back().coefficients_;
    for (Eigen::Index k = 0; k < num_lines; ++k)
      for (int m = 0; m <= n; ++m) c[lines[k * (n + 1) + m]] = part(m, k);
  }
  return out;
}

Eigen::MatrixXd bernstein_elevation_1d(int from, int to) {
  if (from < 0 || to < from)
    throw std::invalid_argument("Bernstein elevation: need 0 <= from <= to, got " + std::to_string(from) +
                                " -> " + std::to_string(to));
  Eigen::MatrixXd elevation = Eigen::MatrixXd::Zero(to + 1, from + 1);
  for (int i = 0; i <= from; ++i)
    for (int j = i; j <= i + to - from; ++j)
      elevation(j, i) = binomial(from, i) * binomial(to - from, j - i) / binomial(to, j);
  return elevation;
}

}  // namespace semimesh::ho
