#ifndef EDYN_COLLISION_DYNAMIC_TREE_HPP
#define EDYN_COLLISION_DYNAMIC_TREE_HPP

#include "edyn/config/assert.hpp"
#include "edyn/ecs/entity.hpp"
#include "edyn/shapes/aabb.hpp"
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace edyn {

namespace detail {

// LIFO stack for tree traversals that lives on the call stack: a balanced tree of a million
// leaves is about 30 levels deep, so the inline buffer covers every practical traversal and
// the heap is touched only by pathologically deep trees.
template<typename T, std::size_t N>
class traversal_stack {
public:
    void push(const T &value) {
        if (count < N) {
            buffer[count] = value;
        } else {
            overflow.push_back(value);
        }
        ++count;
    }

    T pop() noexcept {
        EDYN_ASSERT(count > 0);
        --count;
        if (count < N) return buffer[count];
        auto value = overflow.back();
        overflow.pop_back();
        return value;
    }

    bool empty() const noexcept { return count == 0; }

private:
    std::array<T, N> buffer;
    std::vector<T> overflow;
    std::size_t count{0};
};

// Whether the segment p0 + t * d, t in [0, max_fraction], touches the box (slab test).
bool segment_intersects_aabb(const AABB &aabb, const vector3 &p0, const vector3 &d,
                             scalar max_fraction) noexcept;

} // namespace detail

/// Dynamic bounding volume hierarchy over fattened AABBs, the structure behind the broadphase.
///
/// Leaves carry an entity payload; nodes live in one contiguous vector with a free list (no
/// allocation per node), and ids are indices into it, stable for a leaf's whole life. Insertion
/// picks the sibling by the surface-area heuristic, and every node on the path up is improved by
/// a surface-area-reducing rotation, which also keeps the height O(log n) for sorted insertion
/// orders.
///
/// A leaf stores its AABB grown by `margin` on every side (and by the reach and stretched along
/// the predicted displacement, see move()), so that small motions need no tree update. Queries
/// test the fat AABBs: they may report leaves whose tight AABB does not touch the query box. Not
/// thread-safe: const queries may run concurrently, changes may not.
class dynamic_tree {
public:
    /// Identifier of a node: its index in the node array.
    using node_id = std::int32_t;
    /// The id of no node.
    static constexpr node_id null_node = -1;
    /// Default growth of every side of a leaf's AABB, in metres.
    static constexpr scalar default_margin = scalar(0.03);
    /// A reinserted leaf's AABB is also stretched along the displacement given to move(), by this
    /// many times the displacement, so that a body at constant velocity is not reinserted at
    /// every step...
    static constexpr scalar displacement_multiplier = scalar(8);
    /// ...but by no more than this past the first displacement, so that a fast body's box does
    /// not reach far ahead of it. (At 0.1 m the links of a swinging 100-link chain were
    /// reinserted 70 times a step instead of 31, its step 7 % longer; a larger cap lets a
    /// falling heap's boxes reach further: edyn-bench's 16,384-body pile peaked at 214 MB with
    /// 0.1 m, at 261 MB with 0.5 m.)
    static constexpr scalar max_lookahead = scalar(0.5);
    /// move() reinserts a leaf that still covers its motion all the same when its fat AABB
    /// reaches past the one move() would make now by more than this distance on a side (a fast
    /// body slowed down), so that it does not keep spurious pairs. The broadphase waits until a
    /// proxy has stayed that large for a while (a swinging body slows down at each end of every
    /// swing).
    static constexpr scalar shrink_slack = scalar(0.1);

    /// Creates an empty tree.
    /// @param margin Growth of every side of a leaf's AABB (m).
    /// @throws std::invalid_argument When `margin` is negative or not finite.
    explicit dynamic_tree(scalar margin = default_margin);

    /// Inserts a leaf for `aabb` (stored fattened by the margin).
    /// @param aabb The tight AABB (m); must not be inverted (checked in debug builds only).
    /// @param payload The entity the leaf stands for.
    /// @return The new leaf's id.
    node_id create(const AABB &aabb, entity payload);
    /// Removes a leaf; its id may be reused by a later create().
    /// @param id A leaf's id (checked in debug builds only).
    void destroy(node_id id);

    /// Updates a leaf whose tight AABB is now `aabb`, expected to move by `displacement` and to
    /// grow by at most `reach` on every side (by turning) in the coming step.
    ///
    /// The leaf is reinserted only when its fat AABB no longer covers `aabb` grown by `reach` and
    /// swept along `displacement`, or when it became much larger than needed (shrink_slack). A
    /// reinserted leaf is stretched along `displacement` (displacement_multiplier, max_lookahead)
    /// and grown by the margin or `reach`, whichever is larger, on every side.
    /// So two leaves whose swept boxes overlap always have overlapping fat boxes, however they
    /// got there.
    /// @param id A leaf's id.
    /// @param aabb The leaf's new tight AABB (m).
    /// @param displacement Expected motion in the coming step (m), which stretches the fat AABB.
    /// @param reach Expected growth of every side in the coming step (m), not negative.
    /// @return Whether the leaf was reinserted (its fat AABB changed).
    bool move(node_id id, const AABB &aabb, const vector3 &displacement = vector3_zero, scalar reach = 0);

    /// Whether move() with these arguments would reinsert the leaf; changes nothing, so that
    /// many leaves can be asked at once from several threads.
    /// @param id A leaf's id.
    /// @param aabb The leaf's new tight AABB (m).
    /// @param displacement Expected motion in the coming step (m), as move() takes it.
    /// @param reach Expected growth of every side in the coming step (m), as move() takes it.
    bool needs_move(node_id id, const AABB &aabb, const vector3 &displacement = vector3_zero,
                    scalar reach = 0) const noexcept;

    /// Whether the leaf's fat AABB holds `aabb` grown by `reach` and swept along `displacement`:
    /// move() with these arguments reinserts a leaf that does not, and one that does only when
    /// its fat AABB is too large.
    /// @param id A leaf's id.
    /// @param aabb The leaf's new tight AABB (m).
    /// @param displacement Expected motion in the coming step (m), as move() takes it.
    /// @param reach Expected growth of every side in the coming step (m), as move() takes it.
    bool covers(node_id id, const AABB &aabb, const vector3 &displacement, scalar reach) const noexcept;

    /// Whether the leaf's fat AABB reaches past the one move() would make for these arguments by
    /// more than shrink_slack on a side: move() reinserts such a leaf, though it covers its motion.
    /// @param id A leaf's id.
    /// @param aabb The leaf's new tight AABB (m).
    /// @param displacement Expected motion in the coming step (m), as move() takes it.
    /// @param reach Expected growth of every side in the coming step (m), as move() takes it.
    bool oversized(node_id id, const AABB &aabb, const vector3 &displacement, scalar reach) const noexcept;

    /// Calls `fn(node_id)` for each leaf whose fat AABB intersects `aabb`.
    /// @param aabb The query box (m); touching counts.
    /// @param fn Callable taking a node_id; it may return bool: false stops the query.
    template<typename Fn>
    void query(const AABB &aabb, Fn &&fn) const;

    /// Calls `fn(node_id)` for each leaf whose fat AABB is touched by the segment p0-p1, closest
    /// subtrees not guaranteed first.
    /// @param p0 Start of the segment (m).
    /// @param p1 End of the segment (m).
    /// @param fn Callable taking a node_id. It may return a scalar: the new maximum fraction of
    ///        the segment to consider (e.g. the fraction of a hit on the exact shape); values at
    ///        or above the current maximum leave it unchanged and zero or less stops the query.
    template<typename Fn>
    void raycast(const vector3 &p0, const vector3 &p1, Fn &&fn) const;

    /// As raycast(), with the maximum fraction kept by the caller, so that several trees can
    /// share one shrinking segment.
    /// @param p0 Start of the segment (m).
    /// @param p1 End of the segment (m).
    /// @param max_fraction In: the fraction of the segment to search up to. Out: the fraction
    ///        left (0 when `fn` stopped the query).
    /// @param fn Callable taking a node_id and returning the new maximum fraction.
    template<typename Fn>
    void raycast_bounded(const vector3 &p0, const vector3 &p1, scalar &max_fraction, Fn &&fn) const;

    /// Calls `fn(node_id a, node_id b)` once for each pair of distinct leaves of this tree whose
    /// fat AABBs intersect, in an order that depends only on the tree's structure.
    /// @param fn Callable taking two node ids.
    template<typename Fn>
    void query_pairs(Fn &&fn) const;

    /// Calls `fn(node_id this_leaf, node_id other_leaf)` for each pair of a leaf of this tree and
    /// a leaf of `other` whose fat AABBs intersect.
    /// @param other The other tree.
    /// @param fn Callable taking a node id of this tree and one of `other`.
    template<typename Fn>
    void query_pairs(const dynamic_tree &other, Fn &&fn) const;

    /// The fattened AABB stored for a leaf.
    /// @param id A leaf's id (checked in debug builds only).
    /// @return The fat AABB (m).
    const AABB &get_fat_aabb(node_id id) const noexcept {
        EDYN_ASSERT(is_leaf_id(id), "dynamic_tree: not a leaf");
        return nodes[id].aabb;
    }

    /// The entity a leaf stands for.
    /// @param id A leaf's id (checked in debug builds only).
    /// @return The payload given to create().
    entity get_payload(node_id id) const noexcept {
        EDYN_ASSERT(is_leaf_id(id), "dynamic_tree: not a leaf");
        return nodes[id].payload;
    }

    /// Height of the root (0 for a single leaf, -1 when empty).
    int height() const noexcept { return root == null_node ? -1 : nodes[root].height; }
    /// Number of leaves.
    std::size_t size() const noexcept { return leaf_count; }
    /// Upper bound of the node ids: every node id, leaf or not, is below it.
    std::size_t capacity() const noexcept { return nodes.size(); }
    /// Whether the tree has no leaves.
    bool empty() const noexcept { return leaf_count == 0; }
    /// Growth of every side of a leaf's AABB (m), as given to the constructor.
    scalar margin() const noexcept { return fat_margin; }
    /// Removes every node; all ids become invalid.
    void clear() noexcept;

    /// Checks the whole structure: parent links, heights, every internal AABB containing its
    /// children's, leaf count and free list.
    ///
    /// Linear time; meant for tests.
    /// @return An empty string when valid, otherwise a description of the first problem found.
    std::string validate() const;

private:
    struct node {
        AABB aabb;
        entity payload;
        // Parent, or next free node while the node is in the free list.
        node_id parent;
        node_id child1;
        node_id child2;
        // 0 for leaves, -1 for free nodes.
        std::int32_t height;

        bool is_leaf() const noexcept { return child1 == null_node; }
    };

    bool is_leaf_id(node_id id) const noexcept {
        return id >= 0 && static_cast<std::size_t>(id) < nodes.size() && nodes[id].height == 0;
    }

    node_id allocate_node();
    void free_node(node_id id) noexcept;
    void insert_leaf(node_id leaf);
    void remove_leaf(node_id leaf);
    node_id find_best_sibling(const AABB &box) const noexcept;
    void refit_ancestors(node_id index);
    void refit_node(node_id id) noexcept;
    void exchange(node_id x, node_id y) noexcept;
    void rotate(node_id a) noexcept;
    // `aabb` grown by `grow` on every side and stretched along `stretch`.
    static AABB sweep(const AABB &aabb, const vector3 &stretch, scalar grow) noexcept;
    AABB fatten(const AABB &aabb, const vector3 &displacement, scalar reach) const noexcept;

    std::vector<node> nodes;
    node_id root{null_node};
    node_id free_list{null_node};
    std::size_t leaf_count{0};
    scalar fat_margin;
};

template<typename Fn>
void dynamic_tree::query(const AABB &aabb, Fn &&fn) const {
    if (root == null_node) return;
    detail::traversal_stack<node_id, 64> stack;
    stack.push(root);

    while (!stack.empty()) {
        auto id = stack.pop();
        auto &n = nodes[id];
        if (!intersect(n.aabb, aabb)) continue;

        if (n.is_leaf()) {
            if constexpr (std::is_convertible_v<std::invoke_result_t<Fn &, node_id>, bool>) {
                if (!fn(id)) return;
            } else {
                fn(id);
            }
        } else {
            stack.push(n.child2);
            stack.push(n.child1);
        }
    }
}

template<typename Fn>
void dynamic_tree::raycast(const vector3 &p0, const vector3 &p1, Fn &&fn) const {
    auto max_fraction = scalar(1);
    if constexpr (std::is_void_v<std::invoke_result_t<Fn &, node_id>>) {
        raycast_bounded(p0, p1, max_fraction, [&](node_id id) {
            fn(id);
            return scalar(1);
        });
    } else {
        raycast_bounded(p0, p1, max_fraction, [&](node_id id) { return static_cast<scalar>(fn(id)); });
    }
}

template<typename Fn>
void dynamic_tree::raycast_bounded(const vector3 &p0, const vector3 &p1, scalar &max_fraction,
                                   Fn &&fn) const {
    if (root == null_node || max_fraction <= scalar(0)) return;
    auto d = p1 - p0;
    detail::traversal_stack<node_id, 64> stack;
    stack.push(root);

    while (!stack.empty()) {
        auto id = stack.pop();
        auto &n = nodes[id];
        if (!detail::segment_intersects_aabb(n.aabb, p0, d, max_fraction)) continue;

        if (n.is_leaf()) {
            auto fraction = static_cast<scalar>(fn(id));
            if (fraction <= scalar(0)) {
                max_fraction = 0;
                return;
            }
            if (fraction < max_fraction) max_fraction = fraction;
        } else {
            stack.push(n.child2);
            stack.push(n.child1);
        }
    }
}

template<typename Fn>
void dynamic_tree::query_pairs(Fn &&fn) const {
    if (root == null_node) return;
    detail::traversal_stack<std::pair<node_id, node_id>, 128> stack;
    stack.push({root, root});

    while (!stack.empty()) {
        auto [a, b] = stack.pop();
        auto &na = nodes[a];

        if (a == b) {
            // Pairs inside one subtree: both halves on their own, then across them.
            if (na.is_leaf()) continue;
            stack.push({na.child1, na.child2});
            stack.push({na.child2, na.child2});
            stack.push({na.child1, na.child1});
            continue;
        }

        auto &nb = nodes[b];
        if (!intersect(na.aabb, nb.aabb)) continue;

        if (na.is_leaf() && nb.is_leaf()) {
            fn(a, b);
        } else if (nb.is_leaf() || (!na.is_leaf() && aabb_area(na.aabb) >= aabb_area(nb.aabb))) {
            stack.push({na.child2, b});
            stack.push({na.child1, b});
        } else {
            stack.push({a, nb.child2});
            stack.push({a, nb.child1});
        }
    }
}

template<typename Fn>
void dynamic_tree::query_pairs(const dynamic_tree &other, Fn &&fn) const {
    if (root == null_node || other.root == null_node) return;
    detail::traversal_stack<std::pair<node_id, node_id>, 128> stack;
    stack.push({root, other.root});

    while (!stack.empty()) {
        auto [a, b] = stack.pop();
        auto &na = nodes[a];
        auto &nb = other.nodes[b];
        if (!intersect(na.aabb, nb.aabb)) continue;

        if (na.is_leaf() && nb.is_leaf()) {
            fn(a, b);
        } else if (nb.is_leaf() || (!na.is_leaf() && aabb_area(na.aabb) >= aabb_area(nb.aabb))) {
            stack.push({na.child2, b});
            stack.push({na.child1, b});
        } else {
            stack.push({a, nb.child2});
            stack.push({a, nb.child1});
        }
    }
}

} // namespace edyn

#endif // EDYN_COLLISION_DYNAMIC_TREE_HPP
