#ifndef EDYN_SRC_MATH_ARCTAN2_HPP
#define EDYN_SRC_MATH_ARCTAN2_HPP

// The angle of (x, y), as std::atan2, for the joints, which take several per joint and step.
// In single precision a polynomial: the quotient of the smaller coordinate by the larger is the
// tangent of an angle in [0, pi/4]; above tan(pi/8) it is moved down by pi/4 (tan(a - pi/4) =
// (t - 1) / (t + 1)), and the series of atan to t^17 gives the rest, whose next term is below
// 3e-9. Within 3e-7 rad of the exact angle (std::atan2 for float is within about 1e-7) at about
// 60 % of its time. Zeros, infinities and NaNs go to std::atan2. Double precision uses
// std::atan2.

#include "edyn/math/scalar.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace edyn::detail {

inline scalar arctan2(scalar y, scalar x) noexcept {
#ifdef EDYN_DOUBLE_PRECISION
    return std::atan2(y, x);
#else
    auto ax = std::abs(x), ay = std::abs(y);
    constexpr auto largest = std::numeric_limits<scalar>::max();
    // Not both finite (NaNs fail the comparisons), or both zero.
    if (!(ax <= largest && ay <= largest) || (ax == 0 && ay == 0)) return std::atan2(y, x);
    auto hi = std::max(ax, ay);
    auto t = std::min(ax, ay) / hi;
    constexpr auto tan_eighth_pi = scalar(0.41421356237);
    scalar base = 0;
    if (t > tan_eighth_pi) {
        t = (t - 1) / (t + 1);
        base = pi / 4;
    }
    auto t2 = t * t;
    // 1 - t^2/3 + t^4/5 - ... + t^16/17, from the inside out.
    auto series = scalar(1) / 17;
    series = series * t2 - scalar(1) / 15;
    series = series * t2 + scalar(1) / 13;
    series = series * t2 - scalar(1) / 11;
    series = series * t2 + scalar(1) / 9;
    series = series * t2 - scalar(1) / 7;
    series = series * t2 + scalar(1) / 5;
    series = series * t2 - scalar(1) / 3;
    series = series * t2 + 1;
    auto angle = base + t * series;
    if (ay > ax) angle = pi / 2 - angle;
    if (x < 0) angle = pi - angle;
    return std::copysign(angle, y);
#endif
}

} // namespace edyn::detail

#endif // EDYN_SRC_MATH_ARCTAN2_HPP
