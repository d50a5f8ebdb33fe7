#include "edyn/simulation/contact_events.hpp"

namespace edyn {

namespace {
contact_events &events(registry &registry) { return registry.ctx().emplace<contact_events>(); }
} // namespace

sink<contact_signal_t> on_contact_started(registry &registry) { return sink{events(registry).started}; }
sink<contact_signal_t> on_contact_ended(registry &registry) { return sink{events(registry).ended}; }
sink<contact_point_signal_t> on_contact_point_created(registry &registry) {
    return sink{events(registry).point_created};
}
sink<contact_point_signal_t> on_contact_point_destroyed(registry &registry) {
    return sink{events(registry).point_destroyed};
}

void contact_events::publish(const event &e) {
    switch (e.type) {
    case kind::started:
        started.publish(e.manifold);
        break;
    case kind::point_created:
        point_created.publish(e.manifold, e.id);
        break;
    case kind::point_destroyed:
        point_destroyed.publish(e.manifold, e.id);
        break;
    case kind::ended:
        ended.publish(e.manifold);
        break;
    }
}

void contact_events::deliver(const registry &registry) {
    // Listeners may cause new events (by destroying bodies): those are delivered as well.
    for (std::size_t i = 0; i < pending.size(); ++i) {
        auto e = pending[i];
        if (registry.valid(e.manifold)) publish(e);
    }
    pending.clear();
}

} // namespace edyn
