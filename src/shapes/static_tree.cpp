#include "edyn/shapes/static_tree.hpp"
#include <algorithm>
#include <numeric>

namespace edyn {

namespace {

// Splits `order` at the median of the items' AABB centres along the axis where those centres
// spread the most.
void build_node(static_tree &tree, std::span<const AABB> items, std::uint32_t node_index,
                std::span<std::uint32_t> order) {
    AABB aabb{vector3_max, -vector3_max};
    AABB centres{vector3_max, -vector3_max};
    for (auto i : order) {
        aabb = enclosing_aabb(aabb, items[i]);
        auto c = aabb_center(items[i]);
        centres = {min(centres.min, c), max(centres.max, c)};
    }
    tree.nodes[node_index].aabb = aabb;
    if (order.size() == 1) {
        tree.nodes[node_index].index = order[0];
        tree.nodes[node_index].leaf = true;
        return;
    }
    auto axis = max_index(centres.max - centres.min);
    auto mid = order.size() / 2;
    std::nth_element(order.begin(), order.begin() + mid, order.end(), [&](std::uint32_t a, std::uint32_t b) {
        auto ca = aabb_center(items[a])[axis];
        auto cb = aabb_center(items[b])[axis];
        return ca < cb || (ca == cb && a < b);
    });
    auto first = static_cast<std::uint32_t>(tree.nodes.size());
    tree.nodes.push_back({});
    tree.nodes.push_back({});
    tree.nodes[node_index].index = first;
    tree.nodes[node_index].leaf = false;
    build_node(tree, items, first, order.first(mid));
    build_node(tree, items, first + 1, order.subspan(mid));
}

} // namespace

void static_tree::build(std::span<const AABB> items) {
    nodes.clear();
    if (items.empty()) return;
    std::vector<std::uint32_t> order(items.size());
    std::iota(order.begin(), order.end(), 0u);
    nodes.reserve(2 * items.size() - 1);
    nodes.push_back({});
    build_node(*this, items, 0, order);
}

} // namespace edyn
