#ifndef EDYN_SHAPES_STATIC_TREE_HPP
#define EDYN_SHAPES_STATIC_TREE_HPP

#include "edyn/config/assert.hpp"
#include "edyn/shapes/aabb.hpp"
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

// Bounding volume tree over a fixed set of items (a compound's children, a mesh's triangles),
// built once, top down, by median splits: balanced, so a query visits O(log n) nodes plus those
// it reports. Items are referred to by their index in the span of AABBs the tree was built from.
struct static_tree {
    // nodes[0] is the root. A leaf refers to item `index`; an inner node's two children are
    // nodes[index] and nodes[index + 1].
    struct node {
        AABB aabb;
        std::uint32_t index;
        bool leaf;
    };

    std::vector<node> nodes;

    // Rebuilds the tree over `items` (empty gives an empty tree).
    void build(std::span<const AABB> items);

    bool empty() const noexcept { return nodes.empty(); }

    // Bounds of every item; precondition: not empty.
    const AABB &root_aabb() const noexcept {
        EDYN_ASSERT(!nodes.empty());
        return nodes[0].aabb;
    }

    // Calls func(item_index) for every item whose AABB passes test(aabb), testing a node's AABB
    // before its children's. Items come in a fixed order (depth first, lower half first).
    template<typename Test, typename Func>
    void visit(Test &&test, Func &&func) const {
        if (nodes.empty()) return;
        // Balanced: the depth is at most 33 for 2^32 items.
        std::array<std::uint32_t, 64> stack;
        std::size_t size = 0;
        stack[size++] = 0;
        while (size > 0) {
            const auto &n = nodes[stack[--size]];
            if (!test(n.aabb)) continue;
            if (n.leaf) {
                func(std::size_t(n.index));
            } else {
                EDYN_ASSERT(size + 2 <= stack.size());
                stack[size++] = n.index + 1;
                stack[size++] = n.index;
            }
        }
    }
};

} // namespace edyn

#endif // EDYN_SHAPES_STATIC_TREE_HPP
