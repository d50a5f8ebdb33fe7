#include "edyn_scenes/scenes.hpp"
#include <cmath>

namespace edyn::scenes {

namespace {

// Keeps a and b from colliding: bodies joined at their ends overlap there.
void exclude_pair(registry &registry, entity a, entity b) {
    for (auto [self, other] : {std::pair{a, b}, std::pair{b, a}}) {
        collision_exclusion exclusion{};
        if (auto *current = registry.try_get<collision_exclusion>(self)) exclusion = *current;
        if (exclusion.contains(other) || exclusion.num_entities == collision_exclusion::max_exclusions)
            continue;
        exclusion.entities[exclusion.num_entities++] = other;
        if (registry.all_of<collision_exclusion>(self)) {
            registry.replace<collision_exclusion>(self, exclusion);
        } else {
            registry.emplace<collision_exclusion>(self, exclusion);
        }
    }
}

} // namespace

chain_scene make_chain(registry &registry, unsigned links, scalar link_length, const vector3 &top) {
    chain_scene scene;
    rigidbody_def anchor_def;
    anchor_def.kind = rigidbody_kind::rb_static;
    anchor_def.position = top;
    anchor_def.material.reset();
    scene.anchor = make_rigidbody(registry, anchor_def);

    auto half = link_length / 2;
    rigidbody_def def;
    def.mass = 1;
    def.shape = box_shape{{half * scalar(0.9), scalar(0.05), scalar(0.05)}};
    auto previous = scene.anchor;
    for (unsigned i = 0; i < links; ++i) {
        def.position = top + vector3{link_length * scalar(i) + half, 0, 0};
        auto link = make_rigidbody(registry, def);
        auto joint = make_constraint<point_constraint>(registry, previous, link, [&](point_constraint &c) {
            c.pivot[0] = previous == scene.anchor ? vector3_zero : vector3{half, 0, 0};
            c.pivot[1] = {-half, 0, 0};
        });
        if (previous != scene.anchor) exclude_pair(registry, previous, link);
        scene.links.push_back(link);
        scene.joints.push_back(joint);
        previous = link;
    }
    return scene;
}

bridge_scene make_bridge(registry &registry, unsigned planks, scalar plank_length, scalar height,
                         const vector3 &origin) {
    bridge_scene scene;
    const scalar post_half = scalar(0.25);
    const scalar thickness = scalar(0.05);
    auto half = plank_length / 2;
    // The deck hangs slack, bent by `bend` at each hinge into a symmetric arc, so that a load
    // changes its shape instead of stretching its joints. Plank i points at angle[i] from +x.
    const auto bend = to_radians(2);
    std::vector<scalar> angle(planks);
    std::vector<vector3> start(planks + 1);
    // The deck hangs from the posts' top inner edges, at the planks' mid-thickness.
    start[0] = origin + vector3{0, height - thickness, 0};
    for (unsigned i = 0; i < planks; ++i) {
        angle[i] = -(scalar(planks - 1) / 2 - scalar(i)) * bend;
        start[i + 1] = start[i] + vector3{std::cos(angle[i]), std::sin(angle[i]), 0} * plank_length;
    }
    auto span = start[planks].x - start[0].x;

    rigidbody_def post_def;
    post_def.kind = rigidbody_kind::rb_static;
    post_def.shape = box_shape{{post_half, height / 2, scalar(0.6)}};
    post_def.position = origin + vector3{-post_half, height / 2, 0};
    scene.posts[0] = make_rigidbody(registry, post_def);
    post_def.position = origin + vector3{span + post_half, height / 2, 0};
    scene.posts[1] = make_rigidbody(registry, post_def);

    rigidbody_def def;
    def.mass = 2;
    def.material->friction = scalar(0.8);
    // A little shorter than the spacing, so that the planks can turn at the hinges.
    def.shape = box_shape{{half * scalar(0.96), thickness, scalar(0.5)}};
    auto hinge = [&](entity a, const vector3 &pivotA, entity b, const vector3 &pivotB) {
        auto e = make_constraint<hinge_constraint>(registry, a, b, [&](hinge_constraint &h) {
            h.pivot[0] = pivotA;
            h.pivot[1] = pivotB;
            h.set_axes(vector3_z, vector3_z);
            // Some damping in the joints, as a real deck has, so that it does not sway forever.
            h.damping = 2;
        });
        exclude_pair(registry, a, b);
        scene.hinges.push_back(e);
    };
    const vector3 post_edge{post_half, height / 2 - thickness, 0};
    auto previous = scene.posts[0];
    for (unsigned i = 0; i < planks; ++i) {
        def.position = (start[i] + start[i + 1]) / 2;
        def.orientation = quaternion_axis_angle(vector3_z, angle[i]);
        auto plank = make_rigidbody(registry, def);
        if (i == 0) {
            hinge(previous, post_edge, plank, {-half, 0, 0});
        } else {
            hinge(previous, {half, 0, 0}, plank, {-half, 0, 0});
        }
        scene.planks.push_back(plank);
        previous = plank;
    }
    hinge(previous, {half, 0, 0}, scene.posts[1], {-post_half, height / 2 - thickness, 0});
    return scene;
}

} // namespace edyn::scenes
