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

/// The convex shapes a compound can hold (compounds do not nest).
using compound_child_shape_t =
    std::variant<sphere_shape, box_shape, cylinder_shape, capsule_shape, polyhedron_shape>;

/// Rigid union of convex shapes, each at a position and orientation in the compound's object
/// space; the union may be concave.
///
/// Call add_shape() for every child, then finish(), before the shape is used. In collision
/// results the child index is reported as collision_feature::part. Its mass is shared among the
/// children in proportion to their volumes (see moment_of_inertia()).
///
/// With more than `max_children_without_tree` children, finish() builds a static bounding
/// volume tree so that queries touch only the children whose AABBs they overlap.
struct compound_shape {
    /// One convex piece of the compound, as add_shape() stored it.
    struct child {
        /// The child's shape, in its own object space.
        compound_child_shape_t shape;
        /// Position of the child's origin in the compound's object space (m).
        vector3 position;
        /// Orientation of the child in the compound's object space (unit quaternion).
        quaternion orientation;
        /// Bounds of the child in the compound's object space, taken by add_shape() and finish().
        AABB aabb;
    };

    /// Most children a compound has without a bounding volume tree.
    static constexpr std::size_t max_children_without_tree = 8;

    /// The children, in the order they were added (their index is their collision part number).
    std::vector<child> children;
    /// Tree over the children's AABBs; empty when there are max_children_without_tree children or
    /// fewer.
    static_tree tree;
    /// Whether finish() has been called since the last add_shape(): set by finish(), cleared by
    /// add_shape().
    bool finished{false};

    /// Appends a child; finish() must be called again afterwards.
    /// @param shape The child's shape.
    /// @param position Position of the child's origin in the compound's object space (m).
    /// @param orientation Orientation of the child (unit quaternion, x y z w, within 1e-3 in
    ///        squared length; it is stored normalised).
    /// @throws std::invalid_argument Naming compound_shape, when the shape is invalid (see
    ///         validate_shape()), the position not finite or the orientation not unit length.
    void add_shape(compound_child_shape_t shape, const vector3 &position = vector3_zero,
                   const quaternion &orientation = quaternion_identity);

    /// Completes the shape after the last add_shape(), or after its children were changed in
    /// place (their shapes, positions or orientations changed, children removed): takes every
    /// child's AABB again, builds the bounding volume tree when there are more than
    /// max_children_without_tree children, and sets `finished`. A body's compound changed through
    /// the registry (`patch`, `replace`) is finished again by the simulation.
    /// @throws std::invalid_argument When there are no children.
    void finish();

    /// Calls `func(child_index)` for every child whose AABB overlaps `local_aabb`.
    ///
    /// Precondition: finished (checked in debug builds only).
    /// @param local_aabb The query box in the compound's object space (m); touching counts.
    /// @param func Callable taking a `std::size_t` child index.
    template<typename Func>
    void visit(const AABB &local_aabb, Func &&func) const {
        visit_nodes([&](const AABB &aabb) { return intersect(aabb, local_aabb); }, func);
    }

    /// Calls `func(child_index)` for every child whose AABB the segment [p0, p1] touches.
    ///
    /// Precondition: finished (checked in debug builds only).
    /// @param p0 Start of the segment in the compound's object space (m).
    /// @param p1 End of the segment (m).
    /// @param func Callable taking a `std::size_t` child index.
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
