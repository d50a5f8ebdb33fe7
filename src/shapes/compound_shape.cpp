#include "edyn/shapes/compound_shape.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/shapes/validate_shape.hpp"
#include "invalid_argument.hpp"
#include "validate_compound_child.hpp"

namespace edyn {

using detail::throw_invalid_argument;

void compound_shape::add_shape(compound_child_shape_t shape, const vector3 &position,
                               const quaternion &orientation) {
    try {
        detail::validate_compound_child(shape, position, orientation);
    } catch (const std::invalid_argument &e) {
        throw_invalid_argument("compound_shape: add_shape: ", e.what());
    }
    auto orn = normalize(orientation);
    auto aabb = shape_aabb(shape, position, orn);
    children.push_back({std::move(shape), position, orn, aabb});
    tree.nodes.clear();
    finished = false;
}

void compound_shape::finish() {
    if (children.empty()) {
        throw_invalid_argument("compound_shape: finish: children is empty; call add_shape() first");
    }
    // The children may have been changed in place since add_shape(): their bounds are taken again.
    for (auto &c : children)
        c.aabb = shape_aabb(c.shape, c.position, c.orientation);
    tree.nodes.clear();
    if (children.size() > max_children_without_tree) {
        std::vector<AABB> aabbs;
        aabbs.reserve(children.size());
        for (const auto &c : children)
            aabbs.push_back(c.aabb);
        tree.build(aabbs);
    }
    finished = true;
}

} // namespace edyn
