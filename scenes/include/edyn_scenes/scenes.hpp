#ifndef EDYN_SCENES_SCENES_HPP
#define EDYN_SCENES_SCENES_HPP

#include <cstdint>
#include <edyn/edyn.hpp>
#include <vector>

namespace edyn::scenes {

// A static ground: a plane through the origin with normal +y.
entity make_ground(registry &registry, scalar friction = scalar(0.6), scalar restitution = 0);

// Pyramid of unit boxes (half extent `half_extent`) standing on the ground, `base` boxes wide
// in its bottom row and one box fewer in each row above: base * (base + 1) / 2 boxes. Returns
// the boxes from the bottom row up; the last one is the top box.
std::vector<entity> make_pyramid(registry &registry, unsigned base, scalar half_extent = scalar(0.5),
                                 const vector3 &origin = vector3_zero);

// A vertical tower of `count` boxes, one on top of the other. Returns them bottom up.
std::vector<entity> make_tower(registry &registry, unsigned count, scalar half_extent = scalar(0.5),
                               const vector3 &origin = vector3_zero);

enum class pile_shapes : std::uint8_t {
    // Boxes, spheres, capsules and cylinders in equal share.
    primitives,
    // As primitives, plus convex polyhedra (a fifth of the bodies).
    with_polyhedra
};

// `count` mixed bodies of sizes 0.5 to 1 in a grid `width` bodies wide, dropped from above
// the ground (the layers start at `height` and go up 1.5 m each). Sizes and orientations come
// from a fixed-seed generator, so that the scene is the same on every run.
std::vector<entity> make_pile(registry &registry, unsigned count, unsigned width = 16, scalar height = 2,
                              pile_shapes shapes = pile_shapes::with_polyhedra, std::uint32_t seed = 1);

// A row of spheres of radius 0.5 dropped from `height`, with restitution going from 0 to 1
// in equal increments. The ground's restitution is 0 so each ball's own value sets its bounce
// (the mixed restitution is the larger of the two).
std::vector<entity> make_bouncing_balls(registry &registry, unsigned count, scalar height = 4,
                                        const vector3 &origin = vector3_zero);

} // namespace edyn::scenes

#endif // EDYN_SCENES_SCENES_HPP
