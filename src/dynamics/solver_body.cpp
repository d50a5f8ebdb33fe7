#include "edyn/dynamics/solver_body.hpp"
#include "edyn/math/math.hpp"

namespace edyn {

softness make_softness(scalar hertz, scalar zeta, scalar h) noexcept {
    if (hertz <= 0) return {0, 1, 0};
    // Implicit integration of a damped spring, expressed as a bias velocity plus a mix of the
    // rigid and the accumulated impulse.
    auto omega = pi2 * hertz;
    auto a1 = 2 * zeta + h * omega;
    auto a2 = h * omega * a1;
    auto a3 = scalar(1) / (1 + a2);
    return {omega / a1, a2 * a3, a3};
}

} // namespace edyn
