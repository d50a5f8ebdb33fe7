#include "netbench.hpp"
#include <edyn/networking/networked_components.hpp>

namespace edyn_netbench {

namespace {

// Sleeping bodies are left alone: velocity added to them would pile up unseen until they woke.
void drive_bodies(edyn::registry &registry) {
    auto dt = edyn::get_fixed_dt(registry);
    for (auto [e, d, v, m] :
         registry.view<drive, edyn::linvel, edyn::mass>(edyn::exclude<edyn::sleeping_tag>).each())
        v += d.force * (dt / m.s);
}

} // namespace

void setup_registry(edyn::registry &registry) {
    edyn::register_external_components<drive>(registry);
    edyn::register_networked_components<drive>(registry);
    edyn::set_pre_step_callback(registry, &drive_bodies);
}

void set_drive(edyn::registry &client, edyn::entity local, const edyn::vector3 &force) {
    if (auto *current = client.try_get<drive>(local)) {
        if (current->force == force) return;
        client.patch<drive>(local, [&](drive &d) { d.force = force; });
    } else {
        // No drive yet and none asked for: nothing to send, and the server's body is not woken
        // on a step that depends on when the client got to know it.
        if (force == edyn::vector3_zero) return;
        client.emplace<drive>(local, drive{{}, force});
    }
    if (client.all_of<edyn::sleeping_tag>(local)) edyn::wake_up_entity(client, local);
}

std::size_t awake_bodies(const edyn::registry &server) {
    auto count = std::size_t{0};
    for (auto e : server.view<edyn::dynamic_tag>(edyn::exclude<edyn::sleeping_tag>))
        count += e != edyn::null;
    return count;
}

} // namespace edyn_netbench
