#include "edyn/collision/dynamic_tree.hpp"
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace edyn {

namespace detail {

bool segment_intersects_aabb(const AABB &aabb, const vector3 &p0, const vector3 &d,
                             scalar max_fraction) noexcept {
    auto t_min = scalar(0);
    auto t_max = max_fraction;

    for (int i = 0; i < 3; ++i) {
        if (d[i] == scalar(0)) {
            // Parallel to this slab: inside it for the whole segment or never.
            if (p0[i] < aabb.min[i] || p0[i] > aabb.max[i]) return false;
            continue;
        }

        auto inv = scalar(1) / d[i];
        auto t0 = (aabb.min[i] - p0[i]) * inv;
        auto t1 = (aabb.max[i] - p0[i]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        t_min = std::max(t_min, t0);
        t_max = std::min(t_max, t1);
        if (t_min > t_max) return false;
    }

    return true;
}

} // namespace detail

dynamic_tree::dynamic_tree(scalar margin)
    : fat_margin(margin) {
    if (!(margin >= scalar(0)) || !std::isfinite(margin)) {
        throw std::invalid_argument("dynamic_tree: margin must be non-negative and finite, got " +
                                    std::to_string(margin));
    }
}

void dynamic_tree::clear() noexcept {
    nodes.clear();
    root = null_node;
    free_list = null_node;
    leaf_count = 0;
}

dynamic_tree::node_id dynamic_tree::allocate_node() {
    node_id id;

    if (free_list != null_node) {
        id = free_list;
        free_list = nodes[id].parent;
    } else {
        id = static_cast<node_id>(nodes.size());
        nodes.emplace_back();
    }

    auto &n = nodes[id];
    n.parent = n.child1 = n.child2 = null_node;
    n.height = 0;
    n.payload = null;
    return id;
}

void dynamic_tree::free_node(node_id id) noexcept {
    nodes[id].parent = free_list;
    nodes[id].height = -1;
    free_list = id;
}

AABB dynamic_tree::sweep(const AABB &aabb, const vector3 &stretch, scalar grow) noexcept {
    auto swept = inset(aabb, vector3_one * grow);
    for (int i = 0; i < 3; ++i) {
        if (stretch[i] < 0) {
            swept.min[i] += stretch[i];
        } else {
            swept.max[i] += stretch[i];
        }
    }
    return swept;
}

AABB dynamic_tree::fatten(const AABB &aabb, const vector3 &displacement, scalar reach) const noexcept {
    auto length = edyn::length(displacement);
    auto lookahead = std::min((displacement_multiplier - 1) * length, max_lookahead);
    auto stretch = length > 0 ? displacement * (1 + lookahead / length) : vector3_zero;
    return sweep(aabb, stretch, std::max(reach, fat_margin));
}

dynamic_tree::node_id dynamic_tree::create(const AABB &aabb, entity payload) {
    EDYN_ASSERT(aabb.min.x <= aabb.max.x && aabb.min.y <= aabb.max.y && aabb.min.z <= aabb.max.z,
                "dynamic_tree::create: inverted AABB");
    auto id = allocate_node();
    nodes[id].aabb = fatten(aabb, vector3_zero, 0);
    nodes[id].payload = payload;
    insert_leaf(id);
    ++leaf_count;
    return id;
}

void dynamic_tree::destroy(node_id id) {
    EDYN_ASSERT(is_leaf_id(id), "dynamic_tree::destroy: not a leaf");
    remove_leaf(id);
    free_node(id);
    --leaf_count;
}

bool dynamic_tree::covers(node_id id, const AABB &aabb, const vector3 &displacement,
                          scalar reach) const noexcept {
    EDYN_ASSERT(is_leaf_id(id), "dynamic_tree::covers: not a leaf");
    EDYN_ASSERT(reach >= 0, "dynamic_tree::covers: negative reach");
    return contains(nodes[id].aabb, sweep(aabb, displacement, reach));
}

bool dynamic_tree::oversized(node_id id, const AABB &aabb, const vector3 &displacement,
                             scalar reach) const noexcept {
    EDYN_ASSERT(is_leaf_id(id), "dynamic_tree::oversized: not a leaf");
    auto largest = inset(fatten(aabb, displacement, reach), vector3_one * shrink_slack);
    return !contains(largest, nodes[id].aabb);
}

bool dynamic_tree::needs_move(node_id id, const AABB &aabb, const vector3 &displacement,
                              scalar reach) const noexcept {
    return !covers(id, aabb, displacement, reach) || oversized(id, aabb, displacement, reach);
}

bool dynamic_tree::move(node_id id, const AABB &aabb, const vector3 &displacement, scalar reach) {
    if (!needs_move(id, aabb, displacement, reach)) return false;
    remove_leaf(id);
    nodes[id].aabb = fatten(aabb, displacement, reach);
    insert_leaf(id);
    return true;
}

// Descends from the root choosing, at each level, between making `box` a sibling of the current
// node or going down into one of its children, by the surface-area cost each choice adds to the
// tree (the growth of every ancestor is paid by all choices below it).
dynamic_tree::node_id dynamic_tree::find_best_sibling(const AABB &box) const noexcept {
    auto index = root;

    while (!nodes[index].is_leaf()) {
        auto &n = nodes[index];
        auto area = aabb_area(n.aabb);
        auto combined_area = aabb_area(enclosing_aabb(n.aabb, box));
        // A new parent holding both `index` and the leaf.
        auto cost_here = scalar(2) * combined_area;
        // Every choice below grows this node to the combined box.
        auto inherited = scalar(2) * (combined_area - area);

        auto child_cost = [&](node_id c) {
            auto &cn = nodes[c];
            auto enlarged = aabb_area(enclosing_aabb(cn.aabb, box));
            return (cn.is_leaf() ? enlarged : enlarged - aabb_area(cn.aabb)) + inherited;
        };

        auto cost1 = child_cost(n.child1);
        auto cost2 = child_cost(n.child2);
        if (cost_here < cost1 && cost_here < cost2) break;
        index = cost1 <= cost2 ? n.child1 : n.child2;
    }

    return index;
}

void dynamic_tree::insert_leaf(node_id leaf) {
    if (root == null_node) {
        root = leaf;
        nodes[leaf].parent = null_node;
        return;
    }

    auto sibling = find_best_sibling(nodes[leaf].aabb);
    auto old_parent = nodes[sibling].parent;
    auto new_parent = allocate_node();
    auto &p = nodes[new_parent];
    p.parent = old_parent;
    p.aabb = enclosing_aabb(nodes[sibling].aabb, nodes[leaf].aabb);
    p.height = nodes[sibling].height + 1;
    p.child1 = sibling;
    p.child2 = leaf;
    nodes[sibling].parent = new_parent;
    nodes[leaf].parent = new_parent;

    if (old_parent == null_node) {
        root = new_parent;
    } else if (nodes[old_parent].child1 == sibling) {
        nodes[old_parent].child1 = new_parent;
    } else {
        nodes[old_parent].child2 = new_parent;
    }

    refit_ancestors(new_parent);
}

void dynamic_tree::remove_leaf(node_id leaf) {
    if (leaf == root) {
        root = null_node;
        return;
    }

    auto parent = nodes[leaf].parent;
    auto grand_parent = nodes[parent].parent;
    auto sibling = nodes[parent].child1 == leaf ? nodes[parent].child2 : nodes[parent].child1;

    if (grand_parent == null_node) {
        root = sibling;
        nodes[sibling].parent = null_node;
        free_node(parent);
        return;
    }

    if (nodes[grand_parent].child1 == parent) {
        nodes[grand_parent].child1 = sibling;
    } else {
        nodes[grand_parent].child2 = sibling;
    }

    nodes[sibling].parent = grand_parent;
    free_node(parent);
    // Boxes only shrink on the way up: they are refitted, not rotated. The insertion that usually
    // follows (a move) rotates along its own path.
    for (auto index = grand_parent; index != null_node; index = nodes[index].parent)
        refit_node(index);
}

// Walks up from `index` to the root recomputing boxes and heights, and improving each node by a
// rotation where one lowers the surface area.
void dynamic_tree::refit_ancestors(node_id index) {
    while (index != null_node) {
        refit_node(index);
        rotate(index);
        index = nodes[index].parent;
    }
}

void dynamic_tree::refit_node(node_id id) noexcept {
    auto &n = nodes[id];
    auto &c1 = nodes[n.child1];
    auto &c2 = nodes[n.child2];
    n.aabb = enclosing_aabb(c1.aabb, c2.aabb);
    n.height = 1 + std::max(c1.height, c2.height);
}

// Swaps the positions of x and y in the tree; they have different parents.
void dynamic_tree::exchange(node_id x, node_id y) noexcept {
    auto px = nodes[x].parent;
    auto py = nodes[y].parent;
    auto &slot_x = nodes[px].child1 == x ? nodes[px].child1 : nodes[px].child2;
    auto &slot_y = nodes[py].child1 == y ? nodes[py].child1 : nodes[py].child2;
    slot_x = y;
    slot_y = x;
    nodes[x].parent = py;
    nodes[y].parent = px;
}

// Tree rotation by surface area: with children b and c of `a`, and their children d e and f g,
// a child may trade places with a grandchild on the other side (b-f, b-g, c-d, c-e) or two
// grandchildren may trade places (d-f, d-g). a's box stays the same; the exchange that shrinks
// the sum of the areas of b and c the most is applied. Applied on every insertion
// path it keeps the tree both tight and shallow, without the loss in quality that rotations
// by height alone cause.
void dynamic_tree::rotate(node_id a) noexcept {
    auto &na = nodes[a];
    auto b = na.child1;
    auto c = na.child2;
    auto &nb = nodes[b];
    auto &nc = nodes[c];
    if (nb.is_leaf() && nc.is_leaf()) return;

    auto area_b = aabb_area(nb.aabb);
    auto area_c = aabb_area(nc.aabb);
    auto merged_area = [&](node_id p, node_id q) {
        return aabb_area(enclosing_aabb(nodes[p].aabb, nodes[q].aabb));
    };

    auto best = scalar(0);
    node_id x = null_node, y = null_node;
    auto consider = [&](scalar change, node_id p, node_id q) {
        if (change < best) {
            best = change;
            x = p;
            y = q;
        }
    };

    if (!nc.is_leaf()) {
        // b-f: c becomes {b, g}.
        consider(merged_area(b, nc.child2) - area_c, b, nc.child1);
        consider(merged_area(b, nc.child1) - area_c, b, nc.child2);
    }
    if (!nb.is_leaf()) {
        consider(merged_area(c, nb.child2) - area_b, c, nb.child1);
        consider(merged_area(c, nb.child1) - area_b, c, nb.child2);
    }
    if (!nb.is_leaf() && !nc.is_leaf()) {
        auto d = nb.child1, e = nb.child2, f = nc.child1, g = nc.child2;
        // d-f: b becomes {f, e}, c becomes {d, g}.
        consider(merged_area(f, e) + merged_area(d, g) - area_b - area_c, d, f);
        consider(merged_area(g, e) + merged_area(f, d) - area_b - area_c, d, g);
    }

    if (x == null_node) return;
    auto px = nodes[x].parent;
    auto py = nodes[y].parent;
    exchange(x, y);
    // The parents below `a` first, then a itself.
    if (px != a) refit_node(px);
    if (py != a) refit_node(py);
    refit_node(a);
}

std::string dynamic_tree::validate() const {
    std::size_t free_count = 0;
    for (auto id = free_list; id != null_node; id = nodes[id].parent) {
        if (id < 0 || static_cast<std::size_t>(id) >= nodes.size()) return "free list index out of range";
        if (nodes[id].height != -1) return "free list node " + std::to_string(id) + " is not marked free";
        if (++free_count > nodes.size()) return "free list has a cycle";
    }

    if (root == null_node) {
        if (leaf_count != 0) return "empty tree with leaf count " + std::to_string(leaf_count);
        if (free_count != nodes.size()) return "empty tree with nodes outside the free list";
        return {};
    }

    if (nodes[root].parent != null_node) return "root has a parent";

    std::size_t reached = 0;
    std::size_t leaves = 0;
    std::vector<node_id> stack{root};

    while (!stack.empty()) {
        auto id = stack.back();
        stack.pop_back();
        auto &n = nodes[id];
        auto name = "node " + std::to_string(id);
        if (++reached > nodes.size()) return "structure has a cycle";
        if (n.height < 0) return name + " is free but reachable";

        if (n.is_leaf()) {
            if (n.child2 != null_node) return name + " has only one child";
            if (n.height != 0) return name + " is a leaf of height " + std::to_string(n.height);
            ++leaves;
            continue;
        }

        if (n.child2 == null_node) return name + " has only one child";
        for (auto c : {n.child1, n.child2}) {
            if (nodes[c].parent != id) return name + ": child " + std::to_string(c) + " has another parent";
            if (!contains(n.aabb, nodes[c].aabb))
                return name + ": AABB does not contain child " + std::to_string(c);
        }
        auto expected = 1 + std::max(nodes[n.child1].height, nodes[n.child2].height);
        if (n.height != expected) {
            return name + ": height " + std::to_string(n.height) + ", expected " + std::to_string(expected);
        }
        stack.push_back(n.child1);
        stack.push_back(n.child2);
    }

    if (leaves != leaf_count) {
        return "reached " + std::to_string(leaves) + " leaves, count says " + std::to_string(leaf_count);
    }
    if (reached + free_count != nodes.size()) return "nodes neither reachable nor free";
    return {};
}

} // namespace edyn
