#include "edyn/simulation/interpolation.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/math/math.hpp"
#include "edyn/simulation/discontinuity.hpp"
#include <cmath>

namespace edyn {

namespace {

// Between two steps a body turns little: for turns under about 0.2 rad (cos of the half angle
// above 0.995) the normalised linear blend is within 1e-4 rad of slerp and costs no
// trigonometry, which matters here, once per body per update().
quaternion blend(const quaternion &q0, const quaternion &q1, scalar s) noexcept {
    auto c = dot(q0, q1);
    if (std::abs(c) < scalar(0.995)) return slerp(q0, q1, s);
    auto target = c < 0 ? -q1 : q1;
    return normalize(q0 * (scalar(1) - s) + target * s);
}

} // namespace

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
            present_orn = blend(prev.orientation, orn, alpha);
        });
    auto snap = [](const position &pos, const orientation &orn, present_position &present_pos,
                   present_orientation &present_orn) {
        present_pos = pos;
        present_orn = orn;
    };
    registry.view<position, orientation, present_position, present_orientation, sleeping_tag>().each(snap);
    registry.view<position, orientation, present_position, present_orientation>(exclude<previous_transform>)
        .each(snap);
    registry.view<discontinuity, present_position, present_orientation>().each(
        [](const discontinuity &d, present_position &present_pos, present_orientation &present_orn) {
            present_pos = static_cast<const vector3 &>(present_pos) + d.position_offset;
            present_orn = normalize(d.orientation_offset * present_orn);
        });
}

} // namespace edyn
