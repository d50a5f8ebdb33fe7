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

/// Bounding volume tree over a fixed set of items (a compound's children, a mesh's triangles).
///
/// Built once, top down, by median splits: balanced, so a query visits O(log n) nodes plus those
/// it reports. Items are referred to by their index in the span of AABBs the tree was built from.
struct static_tree {
    /// One node of the tree. nodes[0] is the root. A leaf refers to item `index`; an inner node's
    /// two children are nodes[index] and nodes[index + 1].
    struct node {
        AABB aabb;           ///< Bounds of every item below the node.
        std::uint32_t index; ///< The item of a leaf, or the first child of an inner node.
        bool leaf;           ///< Whether the node is a leaf.
    };

    /// The nodes, root first; empty for an empty tree.
    std::vector<node> nodes;

    /// Rebuilds the tree over `items` (empty gives an empty tree).
    /// @param items The items' AABBs; an item's index in this span is the index queries report.
    void build(std::span<const AABB> items);

    /// Whether the tree has no nodes.
    bool empty() const noexcept { return nodes.empty(); }

    /// Bounds of every item; precondition: not empty (checked in debug builds only).
    const AABB &root_aabb() const noexcept {
        EDYN_ASSERT(!nodes.empty());
        return nodes[0].aabb;
    }

    /// Calls `func(item_index)` for every item whose AABB passes `test(aabb)`, testing a node's
    /// AABB before its children's.
    ///
    /// Items come in a fixed order (depth first, lower half first).
    /// @param test Callable taking a `const AABB &` and returning whether to descend (or report).
    /// @param func Callable taking a `std::size_t` item index.
    template<typename Test, typename Func>
    void visit(Test &&test, Func &&func) const {
        if (nodes.empty() || !test(nodes[0].aabb)) return;
        // Only nodes that passed the test go on the stack: an inner node tests its two children,
        // which lie side by side, before pushing them. Balanced: the depth is at most 33 for 2^32
        // items.
        std::array<std::uint32_t, 64> stack;
        std::size_t size = 0;
        stack[size++] = 0;
        while (size > 0) {
            const auto &n = nodes[stack[--size]];
            if (n.leaf) {
                func(std::size_t(n.index));
                continue;
            }
            auto lower = test(nodes[n.index].aabb);
            auto upper = test(nodes[n.index + 1].aabb);
            EDYN_ASSERT(size + 2 <= stack.size());
            if (upper) stack[size++] = n.index + 1;
            if (lower) stack[size++] = n.index;
        }
    }
};

} // namespace edyn

#endif // EDYN_SHAPES_STATIC_TREE_HPP
