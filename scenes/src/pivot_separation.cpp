#include "edyn_scenes/pivot_separation.hpp"
#include <algorithm>

namespace edyn::scenes {

namespace {

template<typename Joint>
scalar separation(const registry &registry, const Joint &joint) {
    vector3 pivot[2];
    for (int i = 0; i < 2; ++i) {
        pivot[i] = to_world_space(joint.pivot[i], get_rigidbody_origin(registry, joint.body[i]),
                                  registry.get<orientation>(joint.body[i]));
    }
    return distance(pivot[0], pivot[1]);
}

} // namespace

scalar pivot_separation(const registry &registry, const point_constraint &joint) {
    return separation(registry, joint);
}

scalar pivot_separation(const registry &registry, const hinge_constraint &joint) {
    return separation(registry, joint);
}

scalar pivot_separation(const registry &registry, const cvjoint_constraint &joint) {
    return separation(registry, joint);
}

scalar max_pivot_separation(const registry &registry) {
    scalar worst = 0;
    auto visit = [&](const auto &joint) { worst = std::max(worst, pivot_separation(registry, joint)); };
    registry.view<point_constraint>().each(visit);
    registry.view<hinge_constraint>().each(visit);
    registry.view<cvjoint_constraint>().each(visit);
    return worst;
}

} // namespace edyn::scenes
