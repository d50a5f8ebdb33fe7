#include "edyn/simulation/raycast_async.hpp"
#include "async_execution.hpp"
#include "edyn/simulation/world.hpp"
#include "edyn/simulation/world_state.hpp"
#include "pending_replies.hpp"
#include "simulation_worker.hpp"
#include <algorithm>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

pending_replies &queries(registry &registry, const char *function) {
    if (!is_attached(registry))
        throw std::invalid_argument(std::string(function) +
                                    ": the registry is not attached (call edyn::attach first)");
    return registry.ctx().emplace<pending_replies>();
}

query_aabb_result query_aabb(const registry &registry, const AABB &aabb) {
    query_aabb_result result;
    registry.ctx().get<world_state>().broadphase.query(aabb, [&](entity e) {
        if (auto *box = registry.try_get<AABB>(e); box && intersect(*box, aabb)) result.entities.push_back(e);
    });
    std::sort(result.entities.begin(), result.entities.end());
    return result;
}

} // namespace

void run_pending_replies(registry &registry) {
    auto *pending = registry.ctx().find<pending_replies>();
    if (!pending || pending->replies.empty()) return;
    auto replies = std::move(pending->replies);
    pending->replies.clear();
    // Every delegate gets its reply; the first one that threw is rethrown afterwards.
    std::exception_ptr error;
    for (auto &reply : replies) {
        try {
            reply();
        } catch (...) {
            if (!error) error = std::current_exception();
        }
    }
    if (error) std::rethrow_exception(error);
}

raycast_id_type raycast_async(registry &registry, const vector3 &p0, const vector3 &p1,
                              const raycast_delegate_type &delegate,
                              const std::vector<entity> &ignore_entities) {
    auto &pending = queries(registry, "raycast_async");
    if (!delegate)
        throw std::invalid_argument("raycast_async: delegate is empty (nothing to call with the result)");
    if (!isfinite(p0) || !isfinite(p1)) {
        std::ostringstream msg;
        msg << "raycast_async: p0 and p1 must be finite, got p0 = (" << p0.x << ", " << p0.y << ", " << p0.z
            << "), p1 = (" << p1.x << ", " << p1.y << ", " << p1.z << ")";
        throw std::invalid_argument(msg.str());
    }
    auto id = pending.next_id++;
    auto *link = registry.ctx().find<async_execution>();
    if (!link) {
        auto result = raycast(registry, p0, p1, ignore_entities);
        pending.replies.push_back([=] { delegate(id, result, p0, p1); });
        return id;
    }
    link->push([=](worker_context &w) {
        std::vector<entity> ignore;
        for (auto e : ignore_entities) {
            if (auto local = w.find(e); local != null) ignore.push_back(local);
        }
        auto result = raycast(w.reg, p0, p1, ignore);
        result.entity = w.main_of(result.entity);
        w.message.replies.push_back([=](edyn::registry &) { delegate(id, result, p0, p1); });
    });
    return id;
}

query_aabb_id_type query_aabb_async(registry &registry, const AABB &aabb,
                                    const query_aabb_delegate_type &delegate) {
    auto &pending = queries(registry, "query_aabb_async");
    if (!delegate)
        throw std::invalid_argument("query_aabb_async: delegate is empty (nothing to call with the result)");
    if (!isfinite(aabb.min) || !isfinite(aabb.max) ||
        !(aabb.min.x <= aabb.max.x && aabb.min.y <= aabb.max.y && aabb.min.z <= aabb.max.z)) {
        std::ostringstream msg;
        msg << "query_aabb_async: aabb must be finite with min <= max, got min = (" << aabb.min.x << ", "
            << aabb.min.y << ", " << aabb.min.z << "), max = (" << aabb.max.x << ", " << aabb.max.y << ", "
            << aabb.max.z << ")";
        throw std::invalid_argument(msg.str());
    }
    auto id = pending.next_id++;
    auto *link = registry.ctx().find<async_execution>();
    if (!link) {
        auto result = query_aabb(registry, aabb);
        pending.replies.push_back([=] { delegate(id, result); });
        return id;
    }
    link->push([=](worker_context &w) {
        auto result = query_aabb(w.reg, aabb);
        for (auto &e : result.entities)
            e = w.main_of(e);
        std::erase(result.entities, entity{null});
        std::sort(result.entities.begin(), result.entities.end());
        w.message.replies.push_back([=](edyn::registry &) { delegate(id, result); });
    });
    return id;
}

} // namespace edyn
