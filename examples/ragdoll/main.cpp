// A rag doll from a height and a weight, with longer arms edited into its full definition,
// dropped onto the ground: its joints hold (each pair of pivots stays together) while it falls
// and lands, and it comes to rest on the ground.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

// World position of a constraint pivot: pivots are given from each body's origin.
edyn::vector3 pivot_in_world(const edyn::registry &registry, edyn::entity body, const edyn::vector3 &pivot) {
    return edyn::get_rigidbody_origin(registry, body) +
           edyn::rotate(registry.get<edyn::orientation>(body), pivot);
}

template<typename Joint>
edyn::scalar separation(const edyn::registry &registry, const Joint &joint) {
    return edyn::distance(pivot_in_world(registry, joint.body[0], joint.pivot[0]),
                          pivot_in_world(registry, joint.body[1], joint.pivot[1]));
}

// The largest gap between the two pivots of the rag doll's hinges and CV joints (the cones
// only limit swing and have no common point).
edyn::scalar worst_joint_gap(const edyn::registry &registry, const edyn::ragdoll_entities &ragdoll) {
    edyn::scalar worst = 0;
    for (auto entity : ragdoll.constraints()) {
        if (auto *hinge = registry.try_get<edyn::hinge_constraint>(entity))
            worst = std::max(worst, separation(registry, *hinge));
        else if (auto *cv = registry.try_get<edyn::cvjoint_constraint>(entity))
            worst = std::max(worst, separation(registry, *cv));
    }
    return worst;
}

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);

    auto ground_def = edyn::rigidbody_def();
    ground_def.kind = edyn::rigidbody_kind::rb_static;
    ground_def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    edyn::make_rigidbody(registry, ground_def);

    // As in the manual: standing 1 m up, leaning 26 degrees.
    auto rag_def = edyn::ragdoll_simple_def{};
    rag_def.height = 1.8;
    rag_def.weight = 82;
    rag_def.position = {2, 1, -1};
    rag_def.orientation = edyn::quaternion_axis_angle({0, 0, 1}, edyn::to_radians(26));
    rag_def.friction = 0.6;
    rag_def.restitution = 0.2;
    // The full definition, to edit: 10% longer upper arms.
    auto full_def = edyn::make_ragdoll_def_from_simple(rag_def);
    full_def.arm_upper_size.x *= 1.1f;
    auto ragdoll = edyn::make_ragdoll(registry, full_def);

    edyn::scalar worst_gap = 0;
    for (int step = 0; step < 180; ++step) {
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        worst_gap = std::max(worst_gap, worst_joint_gap(registry, ragdoll));
    }

    // At rest: every part still and every centre of mass above the ground.
    edyn::scalar fastest = 0, lowest = 10;
    for (auto body : ragdoll.bodies()) {
        fastest = std::max(fastest, edyn::length(registry.get<edyn::linvel>(body)));
        lowest = std::min(lowest, edyn::scalar(registry.get<edyn::position>(body).y));
    }
    std::printf("%zu bodies, %zu constraints; joints opened by at most %.2f mm over 3 s (under 10)\n",
                ragdoll.bodies().size(), ragdoll.constraints().size(), worst_gap * 1000);
    std::printf("after 3 s the fastest part moves at %.3f m/s (under 0.1) and the lowest centre of mass is "
                "%.3f m above the ground (expected above 0)\n",
                fastest, lowest);
    edyn::detach(registry);
    return worst_gap < 0.01f && fastest < 0.1f && lowest > 0 ? 0 : 1;
}
