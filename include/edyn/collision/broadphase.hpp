#ifndef EDYN_COLLISION_BROADPHASE_HPP
#define EDYN_COLLISION_BROADPHASE_HPP

#include "edyn/collision/dynamic_tree.hpp"
#include "edyn/collision/pair_map.hpp"
#include "edyn/collision/should_collide.hpp"
#include "edyn/ecs/delegate.hpp"
#include "edyn/ecs/fwd.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace edyn {

/// What a body is expected to do in the coming step: its proxy's fat AABB is made to cover it.
struct proxy_motion_estimate {
    vector3 displacement{vector3_zero}; ///< Of its AABB, in the coming step (m).
    scalar reach{0};                    ///< Growth of every side of its AABB by turning (m).
};

/// Estimates a body's motion in the coming step from its velocities, given its entity and its
/// current AABB. Returns false where it cannot (a body moved by setting its position): its
/// proxy then expects the displacement since the last update again.
using motion_estimator = delegate<bool(const registry &, entity, const AABB &, proxy_motion_estimate &)>;

/// Finds the pairs of bodies whose fattened AABBs overlap and keeps one manifold entity (with a
/// contact_manifold component) per pair.
///
/// Each world owns one and runs update() as the first phase of every step; programs normally
/// reach it only through raycasts and queries. Static proxies live in their own tree and never
/// pair with each other. Every pair found is offered to the registry's should_collide function
/// (get_should_collide()) once, when it starts overlapping.
///
/// Ordering is reproducible: proxies are visited in the order of their insertion (a removal moves
/// the last proxy into the hole), new manifolds are created sorted by their bodies' entity values,
/// and nothing depends on hash-table or pointer order. A manifold's body[0] is the body with the
/// lower entity value.
class broadphase {
public:
    /// Updates in a row a proxy's fat AABB must stay too large for its motion (see
    /// dynamic_tree::shrink_slack) before update() shrinks it: half a second at 60 Hz, longer
    /// than a swinging body slows down at each end of its swing.
    static constexpr std::uint16_t shrink_patience = 30;

    /// Creates an empty broadphase.
    /// @param margin Growth of every side of a proxy's AABB (m), as dynamic_tree's margin.
    /// @throws std::invalid_argument When `margin` is negative or not finite.
    explicit broadphase(scalar margin = dynamic_tree::default_margin);

    /// Adds a proxy for `e` with its current AABB.
    ///
    /// Static proxies are never moved by update(). Pairs for it are looked for in the next
    /// update().
    /// @param e The body.
    /// @param aabb Its world-space AABB (m).
    /// @param is_static Whether the body never moves (it then never pairs with other static
    ///        bodies).
    /// @throws std::invalid_argument When `e` is null or already has a proxy (or reuses the index
    ///         of an entity whose proxy was not removed), or when the AABB is inverted or not
    ///         finite.
    void insert(entity e, const AABB &aabb, bool is_static);

    /// Removes the proxy of `e` and destroys the manifold entities of its pairs.
    ///
    /// Not to be called from within update() (e.g. from a contact_manifold construction
    /// listener).
    /// @param registry The registry holding the manifold entities.
    /// @param e The body.
    /// @throws std::invalid_argument When `e` has no proxy.
    void remove(registry &registry, entity e);

    /// Whether `e` has a proxy.
    /// @param e The entity to look for.
    bool contains(entity e) const noexcept;

    /// The fattened AABB pairs are found with.
    /// @param e The body.
    /// @return Its fat AABB in world space (m), valid until the broadphase changes.
    /// @throws std::invalid_argument When `e` has no proxy.
    const AABB &get_fat_aabb(entity e) const;

    /// Asks again whether the pairs of `e` should collide, after its collision_filter or
    /// collision_exclusion changed.
    ///
    /// Destroys its manifolds that the filter now rejects and looks for new pairs in the next
    /// update(). Not to be called from within update().
    /// @param registry The registry holding the bodies and manifolds.
    /// @param e The body.
    /// @throws std::invalid_argument When `e` has no proxy.
    void refilter(registry &registry, entity e);

    /// Moves every dynamic proxy to the AABB component of its entity, destroys the manifolds
    /// whose bodies' fat AABBs no longer overlap and creates manifolds for new overlapping pairs
    /// that should collide.
    ///
    /// A proxy's fat AABB covers where its body is expected to be in the coming step, so that
    /// two bodies that may touch in that step always have a manifold, whatever happened before.
    /// What only reads (which proxies left their fat AABBs, which pairs separated, the new pairs'
    /// search) runs on the scheduler's threads when one is given; the tree and the registry
    /// change on the calling thread, in the same order whatever the number of threads.
    /// @param registry The registry holding the bodies' AABB components; manifold entities are
    ///        created and destroyed in it.
    /// @param scheduler Threads to spread the reading over; null runs it all on the calling
    ///        thread.
    /// @param estimate Each dynamic body's motion in the coming step, called from the scheduler's
    ///        threads; when empty (or where it returns false) a body is expected to move as it
    ///        did since the last update, at most its own size.
    void update(registry &registry, task_scheduler *scheduler = nullptr, motion_estimator estimate = {});

    /// The manifold entity of a pair of bodies, in either order.
    /// @param first One body.
    /// @param second The other body.
    /// @return The manifold entity, or null when the bodies have none.
    entity get_manifold(entity first, entity second) const noexcept;
    /// Number of manifolds (overlapping pairs that should collide).
    std::size_t num_manifolds() const noexcept { return records.size(); }
    /// Number of proxies, dynamic and static.
    std::size_t num_proxies() const noexcept { return dynamic_proxies.size() + static_proxies.size(); }
    /// The body of a proxy: the dynamic ones first, then the static ones; each body once.
    /// @param i A proxy's position, below num_proxies().
    entity proxy_body(std::size_t i) const noexcept {
        return i < dynamic_proxies.size() ? dynamic_proxies[i].body
                                          : static_proxies[i - dynamic_proxies.size()].body;
    }

    /// Calls `fn(entity)` for each body whose fat AABB intersects `aabb`, dynamic ones first.
    /// @param aabb The query box in world space (m).
    /// @param fn Callable taking an entity; it may return bool: false stops the query.
    template<typename Fn>
    void query(const AABB &aabb, Fn &&fn) const;

    /// Calls `fn(entity)` for each body whose fat AABB the segment p0-p1 touches.
    /// @param p0 Start of the segment in world space (m).
    /// @param p1 End of the segment in world space (m).
    /// @param fn Callable taking an entity. It may return a scalar: the new maximum fraction of
    ///        the segment (as dynamic_tree::raycast), shared by both trees.
    template<typename Fn>
    void raycast(const vector3 &p0, const vector3 &p1, Fn &&fn) const;

    /// The tree of the dynamic (and kinematic) bodies' proxies.
    const dynamic_tree &get_dynamic_tree() const noexcept { return trees[0]; }
    /// The tree of the static bodies' proxies.
    const dynamic_tree &get_static_tree() const noexcept { return trees[1]; }

private:
    struct proxy {
        entity body;
        dynamic_tree::node_id node;
        vector3 center; // of the tight AABB last seen, to predict motion
        bool queued;    // in `queue`, waiting for its pair search
        // Updates in a row that found its fat AABB too large for its motion.
        std::uint16_t oversized_updates{0};
    };

    struct locator {
        std::int32_t index{-1};
        bool is_static{false};
    };

    struct manifold_record {
        entity body[2];
        entity manifold;
        dynamic_tree::node_id node[2];
        bool is_static[2];
    };

    struct new_pair {
        entity body[2];
        dynamic_tree::node_id node[2];
        bool is_static[2];
    };

    // A dynamic proxy's motion in the current update.
    struct proxy_motion {
        AABB aabb;
        proxy_motion_estimate expected;
        bool reinsert;
    };

    // A queued proxy whose pairs are looked for.
    struct pair_search {
        entity body;
        dynamic_tree::node_id node;
        bool is_static;
    };

    static std::uint64_t pair_key(entity a, entity b) noexcept;
    const locator *find(entity e) const noexcept;
    proxy &get_proxy(const locator &loc) noexcept;
    dynamic_tree &tree_of(bool is_static) noexcept { return trees[is_static ? 1 : 0]; }
    const dynamic_tree &tree_of(bool is_static) const noexcept { return trees[is_static ? 1 : 0]; }
    void destroy_record(registry &registry, std::size_t index);
    void move_proxies(registry &registry, task_scheduler *scheduler, motion_estimator estimate);
    void destroy_separated(registry &registry, task_scheduler *scheduler);
    void refilter_all(registry &registry, should_collide_func_t filter);
    void destroy_pairs_of(registry &registry, entity e, bool is_static, AABB fat,
                          should_collide_func_t keep_if);
    void collect_new_pairs(task_scheduler *scheduler);
    void search_pairs(const pair_search &search, std::vector<new_pair> &out) const;
    void create_manifolds(registry &registry);

    // Dynamic proxies, then static ones.
    std::array<dynamic_tree, 2> trees;
    std::vector<proxy> dynamic_proxies;
    std::vector<proxy> static_proxies;
    // By entity index.
    std::vector<locator> locators;
    // Proxies inserted, reinserted or refiltered since their last pair search.
    std::vector<entity> queue;
    std::vector<manifold_record> records;
    // Pair key -> position in `records`; only looked up, never iterated.
    pair_map record_of_pair;
    std::vector<new_pair> pairs_scratch;
    // Dynamic tree nodes reinserted in the current update, also flagged by node id: only their
    // pairs can have separated.
    std::vector<dynamic_tree::node_id> moved_nodes;
    std::vector<std::uint8_t> reinserted;
    // Scratch of update(), kept from one to the next: each dynamic proxy's motion, whether each
    // record separated, the searches of the queued proxies and what each block of them found.
    std::vector<proxy_motion> motions;
    std::vector<std::uint8_t> separated;
    std::vector<pair_search> searches;
    std::vector<std::vector<new_pair>> found;
    bool updating{false};
    // The filter the pairs were made with (null before the first update): when the registry's
    // changes, every pair is asked again.
    should_collide_func_t filtered_with{nullptr};
};

template<typename Fn>
void broadphase::query(const AABB &aabb, Fn &&fn) const {
    constexpr bool can_stop = std::is_convertible_v<std::invoke_result_t<Fn &, entity>, bool>;
    bool stopped = false;

    for (auto &tree : trees) {
        tree.query(aabb, [&](dynamic_tree::node_id id) {
            if constexpr (can_stop) {
                stopped = !fn(tree.get_payload(id));
                return !stopped;
            } else {
                fn(tree.get_payload(id));
            }
        });
        if (stopped) return;
    }
}

template<typename Fn>
void broadphase::raycast(const vector3 &p0, const vector3 &p1, Fn &&fn) const {
    if constexpr (std::is_void_v<std::invoke_result_t<Fn &, entity>>) {
        for (auto &tree : trees) {
            tree.raycast(p0, p1, [&](dynamic_tree::node_id id) { fn(tree.get_payload(id)); });
        }
    } else {
        // The second tree is searched only up to the fraction the first one left.
        auto max_fraction = scalar(1);
        for (auto &tree : trees) {
            tree.raycast_bounded(p0, p1, max_fraction, [&](dynamic_tree::node_id id) {
                return static_cast<scalar>(fn(tree.get_payload(id)));
            });
            if (max_fraction <= scalar(0)) return;
        }
    }
}

} // namespace edyn

#endif // EDYN_COLLISION_BROADPHASE_HPP
