#include "edyn/shapes/compound_shape.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/shapes/validate_shape.hpp"
#include "invalid_argument.hpp"
#include <algorithm>
#include <numeric>
#include <span>

namespace edyn {

namespace {

using detail::throw_invalid_argument;

// Top-down build: split the children at the median of their AABB centres along the axis where
// those centres spread the most. Median splits keep the tree balanced.
void build_node(compound_shape &shape, std::uint32_t node_index, std::span<std::uint32_t> items) {
    AABB aabb{vector3_max, -vector3_max};
    AABB centres{vector3_max, -vector3_max};
    for (auto i : items) {
        aabb = enclosing_aabb(aabb, shape.children[i].aabb);
        auto c = aabb_center(shape.children[i].aabb);
        centres = {min(centres.min, c), max(centres.max, c)};
    }
    shape.nodes[node_index].aabb = aabb;
    if (items.size() == 1) {
        shape.nodes[node_index].index = items[0];
        shape.nodes[node_index].leaf = true;
        return;
    }
    auto axis = max_index(centres.max - centres.min);
    auto mid = items.size() / 2;
    std::nth_element(items.begin(), items.begin() + mid, items.end(), [&](std::uint32_t a, std::uint32_t b) {
        auto ca = aabb_center(shape.children[a].aabb)[axis];
        auto cb = aabb_center(shape.children[b].aabb)[axis];
        return ca < cb || (ca == cb && a < b);
    });
    auto first = static_cast<std::uint32_t>(shape.nodes.size());
    shape.nodes.push_back({});
    shape.nodes.push_back({});
    shape.nodes[node_index].index = first;
    shape.nodes[node_index].leaf = false;
    build_node(shape, first, items.first(mid));
    build_node(shape, first + 1, items.subspan(mid));
}

} // namespace

void compound_shape::add_shape(compound_child_shape_t shape, const vector3 &position,
                               const quaternion &orientation) {
    try {
        validate_shape(shape);
    } catch (const std::invalid_argument &e) {
        throw_invalid_argument("compound_shape: add_shape: shape: ", e.what());
    }
    if (!isfinite(position)) {
        throw_invalid_argument("compound_shape: add_shape: position must be finite, got ", position);
    }
    if (!isfinite(orientation) || !is_unit(orientation)) {
        throw_invalid_argument("compound_shape: add_shape: orientation must be a unit quaternion, got ",
                               orientation, " of length ", length(orientation));
    }
    auto orn = normalize(orientation);
    auto aabb = shape_aabb(shape, position, orn);
    children.push_back({std::move(shape), position, orn, aabb});
    nodes.clear();
    finished = false;
}

void compound_shape::finish() {
    if (children.empty()) {
        throw_invalid_argument("compound_shape: finish: children is empty; call add_shape() first");
    }
    nodes.clear();
    if (children.size() > max_children_without_tree) {
        std::vector<std::uint32_t> items(children.size());
        std::iota(items.begin(), items.end(), 0u);
        nodes.reserve(2 * children.size() - 1);
        nodes.push_back({});
        build_node(*this, 0, items);
    }
    finished = true;
}

} // namespace edyn
