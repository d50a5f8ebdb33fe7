#include "edyn/simulation/interpolation.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/math/math.hpp"

namespace edyn {

void save_previous_transforms(registry &registry) {
    registry.view<previous_transform, position, orientation>(exclude<sleeping_tag>)
        .each([](previous_transform &prev, const position &pos, const orientation &orn) {
            prev.position = pos;
            prev.orientation = orn;
        });
}

void interpolate_present_transforms(registry &registry, scalar alpha) {
    registry
        .view<previous_transform, position, orientation, present_position, present_orientation>(
            exclude<sleeping_tag>)
        .each([alpha](const previous_transform &prev, const position &pos, const orientation &orn,
                      present_position &present_pos, present_orientation &present_orn) {
            present_pos = lerp(prev.position, static_cast<const vector3 &>(pos), alpha);
            present_orn = slerp(prev.orientation, orn, alpha);
        });
    auto snap = [](const position &pos, const orientation &orn, present_position &present_pos,
                   present_orientation &present_orn) {
        present_pos = pos;
        present_orn = orn;
    };
    registry.view<position, orientation, present_position, present_orientation, sleeping_tag>().each(snap);
    registry.view<position, orientation, present_position, present_orientation>(exclude<previous_transform>)
        .each(snap);
}

} // namespace edyn
