// Conformal geometric algebra G(4,1): the part the hypothesis generation of paper §2.4 needs.
// Blades (k-vectors) of every grade, the outer product that meets restriction spheres (Eqs. 11-13),
// the left contraction (inner product) that reads centres and radii off the meets, and the dual.
//
// Representation. The algebra is built on R^{4,1} with the orthonormal basis e1, e2, e3, e+, e-
// (e+^2 = 1, e-^2 = -1). The null basis of the conformal model is
//
//   e0   = (e- - e+) / 2   (the origin),             e0^2   = 0,
//   einf = e- + e+         (the point at infinity),  einf^2 = 0,   e0 . einf = -1.
//
// A Euclidean point x and a sphere (centre c, radius r) are the vectors (inner product null space,
// IPNS: the set of points X with X . S = 0)
//
//   P = x + 1/2 x^2 einf + e0,       S = c + 1/2 (c^2 - r^2) einf + e0 = C - 1/2 r^2 einf,
//
// so that P . S = -1/2 (|x - c|^2 - r^2): zero exactly on the sphere. A plane n . x = delta is
// n + delta einf (a sphere through infinity: no e0 part).
//
// A grade-k element stores its C(5, k) coefficients on the basis blades e_A, A a k-subset of the
// basis, encoded as a bit mask (bit 0..4 = e1, e2, e3, e+, e-) and stored in increasing mask order.
// On an orthonormal basis the geometric product of two basis blades is one signed basis blade,
//
//   e_A e_B = reorder_sign(A, B) * metric(A & B) * e_{A xor B},
//
// whose grade-|A|+|B| part is the outer product (non-zero iff A & B = 0) and whose grade-|B|-|A|
// part is the left contraction (non-zero iff A is a subset of B). Every product below is therefore
// a fixed list of signed coefficient products, tabulated at compile time.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace vsl::geometry::cga {

namespace detail {

constexpr int kDimension = 5;

constexpr int binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  int result = 1;
  for (int i = 1; i <= k; ++i) result = result * (n - k + i) / i;
  return result;
}

constexpr int bit_count(unsigned mask) {
  int count = 0;
  for (; mask != 0; mask &= mask - 1) ++count;
  return count;
}

// The masks of the grade-k basis blades, in increasing order: the storage order of Blade<K>.
template <int K>
constexpr std::array<std::uint8_t, binomial(kDimension, K)> basis_masks() {
  std::array<std::uint8_t, binomial(kDimension, K)> masks{};
  int i = 0;
  for (unsigned mask = 0; mask < (1u << kDimension); ++mask) {
    if (bit_count(mask) == K) masks[i++] = static_cast<std::uint8_t>(mask);
  }
  return masks;
}

template <int K>
constexpr int index_of(unsigned mask) {
  constexpr auto kMasks = basis_masks<K>();
  for (int i = 0; i < static_cast<int>(kMasks.size()); ++i) {
    if (kMasks[i] == mask) return i;
  }
  return -1;
}

// Sign of bringing e_A e_B into canonical (increasing) order: each basis vector of A must pass
// every basis vector of B with a lower index, one transposition each.
constexpr int reorder_sign(unsigned a, unsigned b) {
  int swaps = 0;
  for (a >>= 1; a != 0; a >>= 1) swaps += bit_count(a & b);
  return (swaps & 1) ? -1 : 1;
}

// Product of the squares of the basis vectors in A: only e- (bit 4) squares to -1.
constexpr int metric_sign(unsigned a) {
  return (a & 16u) ? -1 : 1;
}

struct Term {
  std::uint8_t lhs;
  std::uint8_t rhs;
  std::uint8_t out;
  std::int8_t sign;
};

template <int A, int B>
constexpr auto wedge_terms() {
  constexpr int kCount = binomial(kDimension, A) * binomial(kDimension - A, B);
  std::array<Term, kCount> terms{};
  int n = 0;
  const auto lhs = basis_masks<A>();
  const auto rhs = basis_masks<B>();
  for (int i = 0; i < static_cast<int>(lhs.size()); ++i) {
    for (int j = 0; j < static_cast<int>(rhs.size()); ++j) {
      if ((lhs[i] & rhs[j]) != 0) continue;
      terms[n++] = {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(j),
                    static_cast<std::uint8_t>(index_of<A + B>(lhs[i] | rhs[j])),
                    static_cast<std::int8_t>(reorder_sign(lhs[i], rhs[j]))};
    }
  }
  return terms;
}

template <int A, int B>
constexpr auto contraction_terms() {
  constexpr int kCount = binomial(kDimension, B) * binomial(B, A);
  std::array<Term, kCount> terms{};
  int n = 0;
  const auto lhs = basis_masks<A>();
  const auto rhs = basis_masks<B>();
  for (int i = 0; i < static_cast<int>(lhs.size()); ++i) {
    for (int j = 0; j < static_cast<int>(rhs.size()); ++j) {
      if ((lhs[i] & rhs[j]) != lhs[i]) continue;
      terms[n++] = {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(j),
                    static_cast<std::uint8_t>(index_of<B - A>(rhs[j] & ~lhs[i])),
                    static_cast<std::int8_t>(reorder_sign(lhs[i], rhs[j]) * metric_sign(lhs[i]))};
    }
  }
  return terms;
}

// out += sum over the terms of sign * lhs[i] * rhs[j], expanded at compile time into straight-line
// code (the term list is a constant, so every index is one).
template <const auto& kTerms, typename Out, typename Lhs, typename Rhs, std::size_t... I>
void accumulate(Out& out, const Lhs& lhs, const Rhs& rhs, std::index_sequence<I...>) {
  ((out[kTerms[I].out] += kTerms[I].sign * (lhs[kTerms[I].lhs] * rhs[kTerms[I].rhs])), ...);
}

template <int A, int B>
inline constexpr auto kWedgeTerms = wedge_terms<A, B>();
template <int A, int B>
inline constexpr auto kContractionTerms = contraction_terms<A, B>();

}  // namespace detail

// Basis vector masks.
inline constexpr unsigned kE1 = 1u;
inline constexpr unsigned kE2 = 2u;
inline constexpr unsigned kE3 = 4u;
inline constexpr unsigned kEPlus = 8u;
inline constexpr unsigned kEMinus = 16u;

// A k-vector of G(4,1) (every blade used here is a k-vector; the type does not check that it
// factors).
template <int K>
class Blade {
  static_assert(K >= 0 && K <= detail::kDimension);

 public:
  static constexpr int kGrade = K;
  static constexpr int kSize = detail::binomial(detail::kDimension, K);
  using Coefficients = Eigen::Matrix<double, kSize, 1>;

  Blade() : coefficients_(Coefficients::Zero()) {}
  explicit Blade(const Coefficients& coefficients) : coefficients_(coefficients) {}

  const Coefficients& coefficients() const { return coefficients_; }
  Coefficients& coefficients() { return coefficients_; }

  // Coefficient on the basis blade `mask` (a grade-K subset of kE1 | kE2 | kE3 | kEPlus | kEMinus).
  double coefficient(unsigned mask) const { return coefficients_[index(mask)]; }
  double& coefficient(unsigned mask) { return coefficients_[index(mask)]; }

  // Largest absolute coefficient: the size of the blade, for relative tolerances.
  double magnitude() const { return coefficients_.cwiseAbs().maxCoeff(); }

  Blade& operator+=(const Blade& other) {
    coefficients_ += other.coefficients_;
    return *this;
  }
  Blade& operator-=(const Blade& other) {
    coefficients_ -= other.coefficients_;
    return *this;
  }
  Blade& operator*=(double factor) {
    coefficients_ *= factor;
    return *this;
  }
  friend Blade operator+(Blade a, const Blade& b) { return a += b; }
  friend Blade operator-(Blade a, const Blade& b) { return a -= b; }
  friend Blade operator-(Blade a) { return a *= -1.0; }
  friend Blade operator*(Blade a, double factor) { return a *= factor; }
  friend Blade operator*(double factor, Blade a) { return a *= factor; }
  friend Blade operator/(Blade a, double divisor) { return a *= 1.0 / divisor; }

 private:
  static int index(unsigned mask) {
    const int i = detail::index_of<K>(mask);
    eigen_assert(i >= 0 && "mask is not a basis blade of this grade");
    return i;
  }

  Coefficients coefficients_;
};

using Scalar = Blade<0>;
using Vector = Blade<1>;
using Bivector = Blade<2>;
using Trivector = Blade<3>;
using Quadvector = Blade<4>;
using Pseudoscalar = Blade<5>;

// Outer (wedge) product A ^ B, grade A + B. For IPNS rounds it is the meet (intersection):
// a circle is S1 ^ S2 (Eq. 11), a point pair S1 ^ S2 ^ S3 (Eq. 12), a point S1 ^ ... ^ S4 (Eq. 13).
template <int A, int B>
Blade<A + B> wedge(const Blade<A>& a, const Blade<B>& b) {
  constexpr const auto& kTerms = detail::kWedgeTerms<A, B>;
  Blade<A + B> result;
  detail::accumulate<kTerms>(result.coefficients(), a.coefficients(), b.coefficients(),
                             std::make_index_sequence<kTerms.size()>{});
  return result;
}

// Left contraction A _| B, grade B - A (only A <= B: the contraction onto a lower grade is zero).
// For a vector a it removes a from B: a _| (b ^ c) = (a . b) c - (a . c) b; for blades with
// span(A) inside span(B) it is the orthogonal complement of A in B.
template <int A, int B>
Blade<B - A> contract(const Blade<A>& a, const Blade<B>& b) {
  static_assert(A <= B, "the left contraction onto a lower grade is zero");
  constexpr const auto& kTerms = detail::kContractionTerms<A, B>;
  Blade<B - A> result;
  detail::accumulate<kTerms>(result.coefficients(), a.coefficients(), b.coefficients(),
                             std::make_index_sequence<kTerms.size()>{});
  return result;
}

// Inner product of two vectors (the metric of R^{4,1}).
inline double inner(const Vector& a, const Vector& b) {
  const auto& x = a.coefficients();
  const auto& y = b.coefficients();
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3] - x[4] * y[4];
}

// Unit pseudoscalar I = e1 e2 e3 e+ e- (I^2 = -1).
inline Pseudoscalar pseudoscalar() {
  Pseudoscalar i;
  i.coefficients()[0] = 1.0;
  return i;
}

// Dual X* = X _| I^-1 with I^-1 = -I. Turns an IPNS blade into its outer product null space form
// and back (up to sign); (a ^ B)* = a _| B*, so the dual of S1 ^ ... ^ Sk is orthogonal to every
// Si.
template <int K>
Blade<detail::kDimension - K> dual(const Blade<K>& x) {
  return contract(x, -pseudoscalar());
}

// Vectors of the conformal model in the null basis: euclidean + e0_part e0 + einf_part einf.
inline Vector make_vector(const Eigen::Vector3d& euclidean, double e0_part, double einf_part) {
  // e0_part e0 + einf_part einf = (einf_part - e0_part / 2) e+ + (einf_part + e0_part / 2) e-.
  Vector v;
  v.coefficients() << euclidean, einf_part - 0.5 * e0_part, einf_part + 0.5 * e0_part;
  return v;
}
inline Eigen::Vector3d euclidean_part(const Vector& v) {
  return v.coefficients().head<3>();
}
// Coefficient on e0, which is -einf . v: 1 for a normalized point or sphere, 0 for a plane.
inline double e0_part(const Vector& v) {
  return v.coefficients()[4] - v.coefficients()[3];
}
// Coefficient on einf, which is -e0 . v.
inline double einf_part(const Vector& v) {
  return 0.5 * (v.coefficients()[3] + v.coefficients()[4]);
}
inline Vector e0() {
  return make_vector(Eigen::Vector3d::Zero(), 1.0, 0.0);
}
inline Vector einf() {
  return make_vector(Eigen::Vector3d::Zero(), 0.0, 1.0);
}

// P = x + 1/2 x^2 einf + e0.
inline Vector point(const Eigen::Vector3d& x_m) {
  return make_vector(x_m, 1.0, 0.5 * x_m.squaredNorm());
}

// S = c + 1/2 (c^2 - r^2) einf + e0 (IPNS), normalized: e0 part 1.
inline Vector sphere(const Eigen::Vector3d& centre_m, double radius_m) {
  return make_vector(centre_m, 1.0, 0.5 * (centre_m.squaredNorm() - radius_m * radius_m));
}

}  // namespace vsl::geometry::cga
