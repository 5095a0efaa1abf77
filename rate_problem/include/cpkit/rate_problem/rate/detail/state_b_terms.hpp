#pragma once
// Internal (installed because RatePrecomputed holds one): the load-independent terms of the
// certified state-b signs of rate_problem/src/rate/certified_b.hpp, where they are formed and
// used. Not an API: the layout may change with the certified route.
namespace cpkit::rate::detail {

/// A double with the magnitude m of the terms it was formed from (the same operations on
/// absolute values): the fast pre-pass of the certified signs (certified_b.hpp, sign3).
struct Mag {
  double v = 0, m = 0;
};

/// The terms of the state-b rate problem that depend on A, C_T and mu only, in T (Mag or
/// Rounded): a map over load directions forms them once per parameter point.
template <class T>
struct BTerms {
  bool applies = false;  ///< the finite-set structure applies (certified_b.hpp, CertifiedB)
  T a11, a12, a22, c1;   ///< c1 = 1 + a11 C_T
  T a12ct;               ///< a12 C_T          (S = c1 dF_N - a12 C_T dF_T)
  T kp, km;              ///< +-1 + mu a12 C_T (L_s = (s + mu a12 C_T) dF_T - mu c1 dF_N)
  T muc1;                ///< mu c1
  T Dp, Dm;              ///< a11 -/+ mu a12   (D_+/- divided by D0 > 0)
  int sp = 0, sm = 0;    ///< their signs
};

}  // namespace cpkit::rate::detail
