// Polynomials in Bernstein (Bezier) form on a product of simplices: a tetrahedron, a triangle x a
// segment (prism), three segments (hexahedron), or lower-dimensional products.
//
// Each factor f is a simplex of dimension d_f in {1,2,3} with barycentric coordinates
// (lambda_0, ..., lambda_d), lambda_0 = 1 - lambda_1 - ... - lambda_d, and a degree n_f. A coefficient
// is indexed by one multi-index per factor, alpha = (alpha_0..alpha_d), |alpha| = n_f; only the
// "free" components alpha_1..alpha_d are stored, one per variable (at most 3 variables in all).
// The basis function of a coefficient is the product over factors of
//   B_alpha(lambda) = n! / (alpha_0! ... alpha_d!) * lambda_0^alpha_0 * ... * lambda_d^alpha_d.
// Facts used (Farin, "Curves and Surfaces for CAGD", ch. on triangular Bezier patches; Lai & Schumaker,
// "Spline Functions on Triangulations", ch. 2): the basis is a non-negative partition of unity, so
// min/max coefficient bound the polynomial; a coefficient at a simplex vertex equals the value there;
// products, derivatives and subdivision map coefficients to coefficients exactly.
#pragma once

#include <Eigen/Core>

#include <array>
#include <memory>
#include <vector>

namespace semimesh::ho {

/// One factor of a product domain: a simplex of dimension 1..3 and a polynomial degree (>= 0).
struct SimplexFactor {
  int dim = 1;
  int degree = 0;
  bool operator==(const SimplexFactor& other) const { return dim == other.dim && degree == other.degree; }
};

/// Enumeration of the multi-indices of one product space; shared by all polynomials of that space.
struct BernsteinLayout {
  std::vector<SimplexFactor> factors;
  int num_vars = 0;                   // sum of the factors' dimensions (<= 3)
  std::array<int, 3> var_factor{};    // factor a variable belongs to
  std::array<int, 3> var_slot{};      // which barycentric coordinate (1..d) of its factor it is
  std::array<int, 3> box_stride{};    // dense (degree+1)^num_vars box holding the free components
  std::vector<std::array<int, 3>> index;  // (size, 3): free components of each coefficient
  std::vector<int> box_to_id;             // box offset -> coefficient id, -1 outside the simplices
  std::vector<double> multinomial;        // product over factors of n! / (alpha_0! ... alpha_d!)
  std::vector<int> corners;               // ids whose multi-index is a vertex of every factor

  int size() const { return static_cast<int>(index.size()); }
  /// Id of the coefficient with these free components, -1 if it is not a valid multi-index.
  int id_of(const std::array<int, 3>& free_components) const;
  /// Full multi-index component alpha_slot (slot 0 = the implicit one) of factor f for coefficient id.
  int component(int id, int factor, int slot) const;

  /// The (cached, thread-safe) layout of a product space. Throws std::invalid_argument when the
  /// dimensions add up to more than 3 or a degree is negative.
  static std::shared_ptr<const BernsteinLayout> get(const std::vector<SimplexFactor>& factors);
};

class BernsteinPolynomial {
 public:
  explicit BernsteinPolynomial(const std::vector<SimplexFactor>& factors);
  explicit BernsteinPolynomial(std::shared_ptr<const BernsteinLayout> layout);

  const BernsteinLayout& layout() const { return *layout_; }
  const std::shared_ptr<const BernsteinLayout>& layout_ptr() const { return layout_; }
  int size() const { return layout_->size(); }
  Eigen::VectorXd& coefficients() { return coefficients_; }
  const Eigen::VectorXd& coefficients() const { return coefficients_; }

  /// Value at a point given per variable by its barycentric coordinate lambda_slot (for a segment
  /// factor that is t in [0, 1]); shape (num_vars) in the layout's variable order.
  double evaluate(const Eigen::Vector3d& point) const;
  /// All basis functions of a layout at one point (same point convention); shape (size).
  static Eigen::VectorXd basis_values(const BernsteinLayout& layout, const Eigen::Vector3d& point);

  /// d/d lambda_var with the factor's other free coordinates fixed (lambda_0 absorbs the change):
  /// d_beta = n (a_{beta + e_var} - a_{beta}); the factor's degree drops by one.
  BernsteinPolynomial derivative(int var) const;
  /// For a segment factor holding variable t: p / (1 - t). Exact when p vanishes at t = 1, i.e. when
  /// the coefficients with alpha_1 = n are zero (they are dropped): B^n_s / (1-t) = n/(n-s) B^{n-1}_s.
  BernsteinPolynomial divide_by_one_minus(int var) const;

  /// Exact product; degrees add factor by factor (both operands must have the same factor dims).
  friend BernsteinPolynomial operator*(const BernsteinPolynomial& a, const BernsteinPolynomial& b);
  /// Sum and difference of polynomials of the same layout.
  friend BernsteinPolynomial operator+(BernsteinPolynomial a, const BernsteinPolynomial& b);
  friend BernsteinPolynomial operator-(BernsteinPolynomial a, const BernsteinPolynomial& b);
  BernsteinPolynomial& operator*=(double scale);

  /// Splits factor `factor` at the midpoint of its edge (vertex_a, vertex_b) (vertices 0..dim) into
  /// two pieces, each expressed in its own Bernstein basis: `first` keeps vertex_a and has vertex_b
  /// replaced by the midpoint, `second` keeps vertex_b and has vertex_a replaced by the midpoint.
  /// (1D de Casteljau at 1/2 along every line alpha_a + alpha_b = const.)
  void bisect(int factor, int vertex_a, int vertex_b, BernsteinPolynomial& first,
              BernsteinPolynomial& second) const;

  /// The same polynomial on the part a <= t <= b (0 <= a < b <= 1) of the segment factor holding
  /// variable `var`, in that part's own Bernstein basis (t = a + (b - a) s, s in [0, 1]): 1D de
  /// Casteljau at b keeping [0, b], then at a / b keeping the rest, along every line of that variable.
  /// Throws std::invalid_argument when `var` is not a segment factor's or the interval is not inside
  /// [0, 1].
  BernsteinPolynomial restricted(int var, double a, double b) const;
  /// restricted(var, a, b) for every interval [a, b] of `intervals`: each one matrix product over
  /// all lines of `var` (the restriction's matrix made once per interval by restricted()'s de
  /// Casteljau on the unit vectors), the same polynomials to round-off. For the pieces of one
  /// element split along one direction (certify_pieces). Throws what restricted() throws.
  std::vector<BernsteinPolynomial> restricted_to_each(int var, const std::vector<std::array<double, 2>>& intervals) const;

 private:
  void check_restriction(int var, double a, double b) const;
  std::shared_ptr<const BernsteinLayout> layout_;
  Eigen::VectorXd coefficients_;
};

/// The product of polynomials of two layouts in the scaled basis (each coefficient times its
/// multinomial), where it is a plain convolution of multi-indices, accumulated in the dense box of
/// the product's layout (BernsteinLayout::box_stride): the kernel of operator*, for callers that
/// chain products without forming the polynomials in between (the Jacobian determinant).
class ScaledProduct {
 public:
  /// Throws std::invalid_argument when the layouts' factor dimensions differ.
  ScaledProduct(const BernsteinLayout& a, const BernsteinLayout& b);
  /// The product's layout (degrees added factor by factor).
  const std::shared_ptr<const BernsteinLayout>& out() const { return out_; }
  /// box[alpha + beta] += factor * a[alpha] * b[beta] over every pair, in the order of a's
  /// coefficients. a [a.size()], b [b.size()]: scaled coefficients; box [out().box_to_id.size()].
  void accumulate(const double* a, const double* b, double factor, double* box) const;
  /// The product's scaled coefficients from its box: out[k] = the box entry of coefficient k;
  /// out [out().size()].
  void gather(const double* box, double* out) const;

  /// A run of b's coefficients with consecutive ids whose places in the box are consecutive too.
  struct BoxRun {
    int first = 0;   // id of the run's first coefficient
    int offset = 0;  // its place in the box
    int length = 0;
  };
  using RunAccumulator = void (*)(const std::vector<BoxRun>&, const double*, double, double*);
  /// b's runs of one length, with the loop for that length (a fixed one the compiler unrolls).
  struct RunGroup {
    std::vector<BoxRun> runs;
    RunAccumulator accumulate = nullptr;
  };

 private:
  std::shared_ptr<const BernsteinLayout> out_;
  std::vector<int> offset_a_;  // [a.size()] place of a's coefficients in the box
  // b's runs grouped by length (a prism's triangle rows are of every length up to its degree +
  // 1): each box entry still gets one term per coefficient of a, in a's order.
  std::vector<RunGroup> groups_b_;
  std::vector<int> places_;  // [out().size()] place of the product's coefficients in the box
};

/// The product a * b term by term, one pair of coefficients at a time: the slow, obviously right
/// reference operator* is tested against, bit for bit (each result coefficient sums its terms in
/// the same order).
BernsteinPolynomial multiply_pairwise(const BernsteinPolynomial& a, const BernsteinPolynomial& b);

/// Degree elevation of a 1D Bernstein basis: column i holds the degree-`to` coefficients of
/// B^from_i, E(j, i) = C(from, i) C(to - from, j - i) / C(to, j). Shape (to + 1, from + 1).
Eigen::MatrixXd bernstein_elevation_1d(int from, int to);

}  // namespace semimesh::ho
