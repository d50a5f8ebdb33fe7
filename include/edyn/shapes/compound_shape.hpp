#ifndef EDYN_SHAPES_COMPOUND_SHAPE_HPP
#define EDYN_SHAPES_COMPOUND_SHAPE_HPP

#include "edyn/config/assert.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/box_shape.hpp"
#include "edyn/shapes/capsule_shape.hpp"
#include "edyn/shapes/cylinder_shape.hpp"
#include "edyn/shapes/polyhedron_shape.hpp"
#include "edyn/shapes/sphere_shape.hpp"
#include "edyn/shapes/static_tree.hpp"
#include <array>
#include <cstdint>
#include <variant>
#include <vector>

namespace edyn {

// The convex shapes a compound can hold.
using compound_child_shape_t =
    std::variant<sphere_shape, box_shape, cylinder_shape, capsule_shape, polyhedron_shape>;

// Rigid union of convex shapes, each at a position and orientation in the compound's object
// space; the union may be concave. Call add_shape() for every child, then finish(), before the
// shape is used. In collision results the child index is reported as collision_feature::part.
//
// With more than `max_children_without_tree` children, finish() builds a static bounding
// volume tree so that queries touch only the children whose AABBs they overlap.
struct compound_shape {
    struct child {
        compound_child_shape_t shape;
        vector3 position;
        quaternion orientation;
        // Bounds of the child in the compound's object space.
        AABB aabb;
    };

    static constexpr std::size_t max_children_without_tree = 8;

    std::vector<child> children;
    // Over the children's AABBs; empty when there are max_children_without_tree children or fewer.
    static_tree tree;
    // Set by finish(), cleared by add_shape().
    bool finished{false};

    // Appends a child. Throws std::invalid_argument naming compound_shape when the shape is
    // invalid (see validate_shape), the position not finite or the orientation not unit length
    // (within 1e-3 in squared length; it is stored normalised).
    void add_shape(compound_child_shape_t shape, const vector3 &position = vector3_zero,
                   const quaternion &orientation = quaternion_identity);

    // Builds the bounding volume tree. Throws std::invalid_argument when there are no children.
    void finish();

    // Calls func(child_index) for every child whose AABB overlaps `local_aabb` (compound object
    // space; touching counts). Precondition: finished.
    template<typename Func>
    void visit(const AABB &local_aabb, Func &&func) const {
        visit_nodes([&](const AABB &aabb) { return intersect(aabb, local_aabb); }, func);
    }

    // Calls func(child_index) for every child whose AABB the segment [p0, p1] (compound object
    // space) touches. Precondition: finished.
    template<typename Func>
    void visit_ray(const vector3 &p0, const vector3 &p1, Func &&func) const {
        visit_nodes([&](const AABB &aabb) { return intersect_segment(aabb, p0, p1); }, func);
    }

private:
    template<typename Test, typename Func>
    void visit_nodes(Test &&test, Func &func) const {
        EDYN_ASSERT(finished, "compound_shape used before finish()");
        if (tree.empty()) {
            for (std::size_t i = 0; i < children.size(); ++i) {
                if (test(children[i].aabb)) func(i);
            }
            return;
        }
        tree.visit(test, func);
    }
};

} // namespace edyn

#endif // EDYN_SHAPES_COMPOUND_SHAPE_HPP
