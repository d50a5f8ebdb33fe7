#include "edyn/simulation/action_list.hpp"
#include "async_execution.hpp"
#include "edyn/simulation/world.hpp"
#include "simulation_worker.hpp"
#include <stdexcept>
#include <string>

namespace edyn::detail {

namespace {

void add_type(registry &registry, const action_type &type) {
    auto &known = registry.ctx().emplace<action_types>().types;
    for (auto &t : known)
        if (t.id == type.id) return;
    known.push_back(type);
}

} // namespace

void register_action_type(registry &registry, const char *function, const action_type &type) {
    if (!is_attached(registry))
        throw std::invalid_argument(std::string(function) +
                                    ": the registry is not attached (call edyn::attach first)");
    add_type(registry, type);
    // The worker's steps empty its lists too.
    if (auto *link = registry.ctx().find<async_execution>())
        link->push([type](worker_context &w) { add_type(w.reg, type); });
}

void consume_actions(registry &registry) {
    auto *types = registry.ctx().find<action_types>();
    if (!types) return;
    if (types->before_clear) types->before_clear(registry);
    if (auto *sink = find_replication_sink(registry))
        for (auto &t : types->types)
            t.send(registry, *sink);
    for (auto &t : types->types)
        t.clear(registry);
}

} // namespace edyn::detail
