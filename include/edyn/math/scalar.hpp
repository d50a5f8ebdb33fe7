#ifndef EDYN_MATH_SCALAR_HPP
#define EDYN_MATH_SCALAR_HPP

#include <limits>

namespace edyn {

// Games use float; large worlds build with -DEDYN_DOUBLE_PRECISION=ON for double.
#ifdef EDYN_DOUBLE_PRECISION
using scalar = double;
#else
using scalar = float;
#endif

inline constexpr scalar pi = scalar(3.14159265358979323846);
inline constexpr scalar half_pi = pi / 2;
inline constexpr scalar pi2 = pi * 2;
inline constexpr scalar large_scalar = std::numeric_limits<scalar>::max();
// Tolerance for geometric degeneracy tests (normalisation, parallel vectors), not for physics.
inline constexpr scalar epsilon = std::numeric_limits<scalar>::epsilon() * 16;

} // namespace edyn

#endif // EDYN_MATH_SCALAR_HPP
