#ifndef EDYN_MATH_SCALAR_HPP
#define EDYN_MATH_SCALAR_HPP

#include <limits>

namespace edyn {

/// The floating-point type of every quantity in edyn: `float` by default, `double` when edyn is
/// built with `-DEDYN_DOUBLE_PRECISION=ON`. Games use float; large worlds build with double.
/// The application must be compiled with the same choice as the library (see
/// `built_with_double_precision`).
#ifdef EDYN_DOUBLE_PRECISION
using scalar = double;
#else
using scalar = float;
#endif

/// The ratio of a circle's circumference to its diameter, in radians for half a turn.
inline constexpr scalar pi = scalar(3.14159265358979323846);
/// A quarter turn, pi / 2 radians.
inline constexpr scalar half_pi = pi / 2;
/// A full turn, 2 pi radians.
inline constexpr scalar pi2 = pi * 2;
/// The largest finite `scalar`, used as "infinitely far" (for example empty bounds, no hit).
inline constexpr scalar large_scalar = std::numeric_limits<scalar>::max();
/// Tolerance for geometric degeneracy tests (normalisation, parallel vectors), not for physics:
/// 16 times the machine epsilon of `scalar`.
inline constexpr scalar epsilon = std::numeric_limits<scalar>::epsilon() * 16;

} // namespace edyn

#endif // EDYN_MATH_SCALAR_HPP
