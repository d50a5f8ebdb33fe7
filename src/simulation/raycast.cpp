#include "edyn/simulation/raycast.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/simulation/settings.hpp"
#include "edyn/simulation/world_state.hpp"
#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace edyn {

raycast_result raycast(const registry &registry, const vector3 &p0, const vector3 &p1,
                       const std::vector<entity> &ignore_entities) {
    const auto *world = registry.ctx().find<world_state>();
    if (!world)
        throw std::invalid_argument("edyn::raycast: the registry is not attached (call edyn::attach)");
    if (registry.ctx().get<settings>().execution_mode == execution_mode::asynchronous)
        throw std::invalid_argument(
            "edyn::raycast: in the asynchronous mode the bodies live in the simulation "
            "worker; use raycast_async (raycast works inside step callbacks)");
    if (!isfinite(p0) || !isfinite(p1)) {
        std::ostringstream msg;
        msg << "edyn::raycast: p0 and p1 must be finite, got p0 = (" << p0.x << ", " << p0.y << ", " << p0.z
            << "), p1 = (" << p1.x << ", " << p1.y << ", " << p1.z << ")";
        throw std::invalid_argument(msg.str());
    }

    raycast_result best;
    world->broadphase.raycast(p0, p1, [&](entity e) -> scalar {
        if (!registry.all_of<shape_index>(e) ||
            std::find(ignore_entities.begin(), ignore_entities.end(), e) != ignore_entities.end()) {
            return best.fraction;
        }
        auto ctx = raycast_context{get_rigidbody_origin(registry, e), registry.get<orientation>(e), p0, p1};
        auto hit = visit_shape(registry, e, [&](const auto &shape) { return shape_raycast(shape, ctx); });
        if (!hit.hit()) return best.fraction;
        if (hit.fraction < best.fraction || (hit.fraction == best.fraction && e < best.entity)) {
            best.entity = e;
            best.fraction = hit.fraction;
            best.normal = hit.normal;
            best.info_var = hit.info_var;
        }
        // Keep looking up to the best hit, inclusive, so that ties are settled by entity value.
        return std::max(best.fraction, std::numeric_limits<scalar>::min());
    });
    return best;
}

} // namespace edyn
