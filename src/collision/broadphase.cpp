#include "edyn/collision/broadphase.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/collision/should_collide.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

void validate_aabb(const AABB &aabb) {
    const char *axes = "xyz";
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(aabb.min[i]) || !std::isfinite(aabb.max[i])) {
            throw std::invalid_argument(std::string("broadphase::insert: aabb.min.") + axes[i] +
                                        " and aabb.max." + axes[i] + " must be finite, got " +
                                        std::to_string(aabb.min[i]) + " and " + std::to_string(aabb.max[i]));
        }
        if (aabb.min[i] > aabb.max[i]) {
            throw std::invalid_argument(std::string("broadphase::insert: aabb.min.") + axes[i] +
                                        " must not exceed aabb.max." + axes[i] + ", got " +
                                        std::to_string(aabb.min[i]) + " > " + std::to_string(aabb.max[i]));
        }
    }
}

// Keeps `updating` true for the duration of update(), exceptions included.
struct update_guard {
    bool &flag;
    explicit update_guard(bool &f)
        : flag(f) {
        flag = true;
    }
    ~update_guard() { flag = false; }
    update_guard(const update_guard &) = delete;
    update_guard &operator=(const update_guard &) = delete;
};

// A body without an estimate is expected to move as it did since the last update; a teleport
// must not turn into a huge box, so that is capped at the body's own size (or the margin, for
// tiny bodies).
vector3 predicted_displacement(const AABB &aabb, const vector3 &displacement, scalar margin) {
    auto cap = std::max(max_component(aabb.max - aabb.min), margin);
    auto len_sqr = length_sqr(displacement);
    if (len_sqr > cap * cap) return displacement * (cap / std::sqrt(len_sqr));
    return displacement;
}

// Work per parallel range in update(): proxies whose motion is looked at, records whose fat AABBs
// are compared, queued proxies whose pairs are searched.
constexpr std::size_t proxies_per_task = 256;
constexpr std::size_t records_per_task = 512;
constexpr std::size_t searches_per_task = 32;

} // namespace

broadphase::broadphase(scalar margin)
    : trees{dynamic_tree(margin), dynamic_tree(margin)} {}

std::uint64_t broadphase::pair_key(entity a, entity b) noexcept {
    auto lo = std::min(to_integral(a), to_integral(b));
    auto hi = std::max(to_integral(a), to_integral(b));
    return (std::uint64_t{lo} << 32) | hi;
}

const broadphase::locator *broadphase::find(entity e) const noexcept {
    auto idx = to_index(e);
    if (e == null || idx >= locators.size() || locators[idx].index < 0) return nullptr;
    auto &loc = locators[idx];
    auto &list = loc.is_static ? static_proxies : dynamic_proxies;
    return list[static_cast<std::size_t>(loc.index)].body == e ? &loc : nullptr;
}

broadphase::proxy &broadphase::get_proxy(const locator &loc) noexcept {
    auto &list = loc.is_static ? static_proxies : dynamic_proxies;
    return list[static_cast<std::size_t>(loc.index)];
}

bool broadphase::contains(entity e) const noexcept { return find(e) != nullptr; }

const AABB &broadphase::get_fat_aabb(entity e) const {
    auto *loc = find(e);
    if (loc == nullptr) {
        throw std::invalid_argument("broadphase::get_fat_aabb: " + detail::describe(e) + " has no proxy");
    }
    auto &list = loc->is_static ? static_proxies : dynamic_proxies;
    return tree_of(loc->is_static).get_fat_aabb(list[static_cast<std::size_t>(loc->index)].node);
}

void broadphase::insert(entity e, const AABB &aabb, bool is_static) {
    if (e == null) throw std::invalid_argument("broadphase::insert: entity must not be null");
    validate_aabb(aabb);
    auto idx = to_index(e);
    if (idx < locators.size() && locators[idx].index >= 0) {
        throw std::invalid_argument("broadphase::insert: " + detail::describe(e) +
                                    (contains(e)
                                         ? " already has a proxy"
                                         : " reuses the index of an entity whose proxy was not removed"));
    }

    auto node = tree_of(is_static).create(aabb, e);
    auto &list = is_static ? static_proxies : dynamic_proxies;
    if (idx >= locators.size()) locators.resize(idx + 1);
    locators[idx] = {static_cast<std::int32_t>(list.size()), is_static};
    list.push_back({e, node, aabb_center(aabb), true});
    queue.push_back(e);
}

void broadphase::remove(registry &registry, entity e) {
    EDYN_ASSERT(!updating, "broadphase::remove: called during update");
    auto *loc = find(e);
    if (loc == nullptr) {
        throw std::invalid_argument("broadphase::remove: " + detail::describe(e) + " has no proxy");
    }

    auto is_static = loc->is_static;
    auto &tree = tree_of(is_static);
    destroy_pairs_of(registry, e, is_static, tree.get_fat_aabb(get_proxy(*loc).node), nullptr);

    // Looked up again: destruction listeners may have inserted or removed proxies.
    loc = find(e);
    if (loc == nullptr) return;
    auto pos = static_cast<std::size_t>(loc->index);
    auto &list = is_static ? static_proxies : dynamic_proxies;
    tree.destroy(list[pos].node);
    if (pos + 1 != list.size()) {
        list[pos] = list.back();
        locators[to_index(list[pos].body)].index = static_cast<std::int32_t>(pos);
    }
    list.pop_back();
    locators[to_index(e)].index = -1;
}

void broadphase::refilter(registry &registry, entity e) {
    EDYN_ASSERT(!updating, "broadphase::refilter: called during update");
    auto *loc = find(e);
    if (loc == nullptr) {
        throw std::invalid_argument("broadphase::refilter: " + detail::describe(e) + " has no proxy");
    }

    auto is_static = loc->is_static;
    auto fat = tree_of(is_static).get_fat_aabb(get_proxy(*loc).node);
    destroy_pairs_of(registry, e, is_static, fat, get_should_collide(registry));

    // Looked up again: destruction listeners may have inserted or removed proxies.
    loc = find(e);
    if (loc == nullptr) return;
    auto &p = get_proxy(*loc);
    if (!p.queued) {
        p.queued = true;
        queue.push_back(e);
    }
}

void broadphase::destroy_pairs_of(registry &registry, entity e, bool is_static, AABB fat,
                                  should_collide_func_t keep_if) {
    // Every manifold joins bodies whose fat AABBs overlap (update() destroys the others), so the
    // pairs of `e` are among the bodies its fat AABB touches. They are destroyed in the order of
    // their keys, not in the trees' order, which depends on the history of the trees.
    std::vector<std::uint64_t> keys;
    for (int t = 0; t < (is_static ? 1 : 2); ++t) {
        auto &other_tree = trees[t];
        other_tree.query(fat, [&](dynamic_tree::node_id id) {
            auto key = pair_key(e, other_tree.get_payload(id));
            if (record_of_pair.contains(key)) keys.push_back(key);
        });
    }
    std::sort(keys.begin(), keys.end());

    for (auto key : keys) {
        auto *index = record_of_pair.find(key);
        if (index == nullptr) continue; // a destruction listener got there first
        auto &rec = records[*index];
        if (keep_if != nullptr && keep_if(registry, rec.body[0], rec.body[1])) continue;
        destroy_record(registry, *index);
    }
}

entity broadphase::get_manifold(entity first, entity second) const noexcept {
    auto *index = record_of_pair.find(pair_key(first, second));
    return index ? records[*index].manifold : null;
}

void broadphase::destroy_record(registry &registry, std::size_t index) {
    auto manifold = records[index].manifold;
    record_of_pair.erase(pair_key(records[index].body[0], records[index].body[1]));

    if (index + 1 != records.size()) {
        records[index] = records.back();
        record_of_pair.insert_or_assign(pair_key(records[index].body[0], records[index].body[1]),
                                        static_cast<std::uint32_t>(index));
    }
    records.pop_back();

    // Last, so that destruction listeners see consistent bookkeeping.
    if (registry.valid(manifold)) registry.destroy(manifold);
}

void broadphase::destroy_separated(registry &registry, task_scheduler *scheduler) {
    auto moved = [&](const manifold_record &rec, int i) {
        return !rec.is_static[i] && reinserted[rec.node[i]] != 0;
    };
    separated.resize(records.size());
    parallel_for(scheduler, std::size_t(0), records.size(), records_per_task, [&](std::size_t i) {
        auto &rec = records[i];
        separated[i] = (moved(rec, 0) || moved(rec, 1)) &&
                       !intersect(tree_of(rec.is_static[0]).get_fat_aabb(rec.node[0]),
                                  tree_of(rec.is_static[1]).get_fat_aabb(rec.node[1]));
    });

    for (std::size_t i = 0; i < records.size();) {
        if (!separated[i]) {
            ++i;
            continue;
        }
        // The last record, and its flag, move into `i` and are visited next.
        separated[i] = separated.back();
        separated.pop_back();
        destroy_record(registry, i);
    }
}

void broadphase::refilter_all(registry &registry, should_collide_func_t filter) {
    // The pairs the new filter refuses, destroyed in the order of their keys.
    std::vector<std::uint64_t> keys;
    for (auto &rec : records)
        if (!filter(registry, rec.body[0], rec.body[1])) keys.push_back(pair_key(rec.body[0], rec.body[1]));
    std::sort(keys.begin(), keys.end());
    for (auto key : keys) {
        if (auto *index = record_of_pair.find(key)) destroy_record(registry, *index);
    }
    // Overlapping pairs the old filter refused have no record: every proxy searches again.
    for (auto *proxies : {&dynamic_proxies, &static_proxies}) {
        for (auto &p : *proxies) {
            if (p.queued) continue;
            p.queued = true;
            queue.push_back(p.body);
        }
    }
}

void broadphase::search_pairs(const pair_search &search, std::vector<new_pair> &out) const {
    auto fat = tree_of(search.is_static).get_fat_aabb(search.node);
    for (int t = 0; t < (search.is_static ? 1 : 2); ++t) {
        auto &other_tree = trees[t];
        other_tree.query(fat, [&](dynamic_tree::node_id id) {
            auto other = other_tree.get_payload(id);
            auto e = search.body;
            if (other == e || record_of_pair.contains(pair_key(e, other))) return;
            new_pair pair{{e, other}, {search.node, id}, {search.is_static, t == 1}};
            if (to_integral(other) < to_integral(e)) {
                std::swap(pair.body[0], pair.body[1]);
                std::swap(pair.node[0], pair.node[1]);
                std::swap(pair.is_static[0], pair.is_static[1]);
            }
            out.push_back(pair);
        });
    }
}

void broadphase::collect_new_pairs(task_scheduler *scheduler) {
    searches.clear();
    for (auto e : queue) {
        auto *loc = find(e);
        if (loc == nullptr) continue; // removed since it was queued
        auto &p = get_proxy(*loc);
        if (!p.queued) continue; // queued twice
        p.queued = false;
        searches.push_back({e, p.node, loc->is_static});
    }
    queue.clear();

    // Each block of searches fills its own list; create_manifolds sorts what they found.
    auto num_blocks = (searches.size() + searches_per_task - 1) / searches_per_task;
    if (found.size() < num_blocks) found.resize(num_blocks);
    parallel_for(scheduler, std::size_t(0), num_blocks, 1, [&](std::size_t b) {
        found[b].clear();
        auto last = std::min((b + 1) * searches_per_task, searches.size());
        for (auto i = b * searches_per_task; i < last; ++i)
            search_pairs(searches[i], found[b]);
    });
    for (std::size_t b = 0; b < num_blocks; ++b)
        pairs_scratch.insert(pairs_scratch.end(), found[b].begin(), found[b].end());
}

void broadphase::create_manifolds(registry &registry) {
    auto less = [](const new_pair &a, const new_pair &b) {
        auto a0 = to_integral(a.body[0]), b0 = to_integral(b.body[0]);
        return a0 != b0 ? a0 < b0 : to_integral(a.body[1]) < to_integral(b.body[1]);
    };
    auto same = [](const new_pair &a, const new_pair &b) {
        return a.body[0] == b.body[0] && a.body[1] == b.body[1];
    };
    std::sort(pairs_scratch.begin(), pairs_scratch.end(), less);
    pairs_scratch.erase(std::unique(pairs_scratch.begin(), pairs_scratch.end(), same), pairs_scratch.end());

    auto should_collide = get_should_collide(registry);

    for (auto &pair : pairs_scratch) {
        if (!should_collide(registry, pair.body[0], pair.body[1])) continue;
        auto manifold_entity = registry.create();
        record_of_pair.insert_or_assign(pair_key(pair.body[0], pair.body[1]),
                                        static_cast<std::uint32_t>(records.size()));
        records.push_back({{pair.body[0], pair.body[1]},
                           manifold_entity,
                           {pair.node[0], pair.node[1]},
                           {pair.is_static[0], pair.is_static[1]}});
        contact_manifold manifold;
        manifold.body = {pair.body[0], pair.body[1]};
        registry.emplace<contact_manifold>(manifold_entity, manifold);
    }

    pairs_scratch.clear();
}

void broadphase::move_proxies(registry &registry, task_scheduler *scheduler, motion_estimator estimate) {
    auto &tree = trees[0];
    // Which proxies no longer cover their motion is found at once...
    motions.resize(dynamic_proxies.size());
    parallel_for(scheduler, std::size_t(0), dynamic_proxies.size(), proxies_per_task, [&](std::size_t i) {
        auto &p = dynamic_proxies[i];
        auto &motion = motions[i];
        motion.reinsert = false;
        auto *aabb = registry.try_get<AABB>(p.body);
        EDYN_ASSERT(aabb != nullptr, "broadphase::update: dynamic proxy without an AABB component");
        if (aabb == nullptr) return;

        auto center = aabb_center(*aabb);
        motion.aabb = *aabb;
        motion.expected = {};
        if (!estimate || !estimate(registry, p.body, *aabb, motion.expected)) {
            motion.expected = {predicted_displacement(*aabb, center - p.center, tree.margin()), 0};
        }
        auto &[displacement, reach] = motion.expected;
        if (!tree.covers(p.node, *aabb, displacement, reach)) {
            motion.reinsert = true;
        } else if (tree.oversized(p.node, *aabb, displacement, reach)) {
            // Too large: shrunk only once it stays so, not at each end of a swing.
            motion.reinsert = ++p.oversized_updates > shrink_patience;
        } else {
            p.oversized_updates = 0;
        }
        p.center = center;
    });

    // ...then those are reinserted, in the proxies' order.
    moved_nodes.clear();
    for (std::size_t i = 0; i < dynamic_proxies.size(); ++i) {
        auto &motion = motions[i];
        if (!motion.reinsert) continue;
        auto &p = dynamic_proxies[i];
        tree.move(p.node, motion.aabb, motion.expected.displacement, motion.expected.reach);
        p.oversized_updates = 0;
        moved_nodes.push_back(p.node);
        if (!p.queued) {
            p.queued = true;
            queue.push_back(p.body);
        }
    }
}

void broadphase::update(registry &registry, task_scheduler *scheduler, motion_estimator estimate) {
    EDYN_ASSERT(!updating, "broadphase::update: called recursively");
    update_guard guard(updating);
    if (auto filter = get_should_collide(registry); filter != filtered_with) {
        if (filtered_with != nullptr) refilter_all(registry, filter);
        filtered_with = filter;
    }
    move_proxies(registry, scheduler, estimate);

    reinserted.resize(trees[0].capacity());
    for (auto node : moved_nodes)
        reinserted[node] = 1;
    destroy_separated(registry, scheduler);
    for (auto node : moved_nodes)
        reinserted[node] = 0;

    collect_new_pairs(scheduler);
    create_manifolds(registry);
}

} // namespace edyn
