#ifndef EDYN_EXAMPLES_NETWORKING_SHARED_HPP
#define EDYN_EXAMPLES_NETWORKING_SHARED_HPP

// What edyn-example-server and edyn-example-client must agree on: the program's networked
// components, registered in the same order on both ends, and the step callback that gives the
// clients' input its meaning. Both ends run the callback: the server to move the body for
// real, the client to extrapolate the server's past state to the present.
#include <chrono>
#include <cstdint>
#include <edyn/edyn.hpp>
#include <edyn/networking/client.hpp>
#include <edyn/networking/networked_components.hpp>
#include <edyn/networking/networked_tag.hpp>
#include <edyn/networking/remote_client.hpp>
#include <edyn/networking/server.hpp>
#include <edyn/serialization/math_types.hpp>
#include <edyn/serialization/memory_archive.hpp>

namespace example {

// ENet channels: what must arrive goes through the reliable one, snapshots (which repeat recent
// changes many times a second) through the unsequenced one, where a lost packet stalls nothing.
inline constexpr std::uint8_t reliable_channel = 0;
inline constexpr std::uint8_t unreliable_channel = 1;
inline constexpr std::size_t channel_count = 2;

// Dynamic boxes the server puts in its scene before anyone connects; a client that sees fewer
// has not received the whole world.
inline constexpr int scene_box_count = 6;
inline constexpr edyn::scalar box_mass = 10;

// A client's input on the box it drives: a horizontal force in newtons. Derived from
// network_input, so the server accepts it only from the box's owner.
struct drive_input : edyn::network_input {
    edyn::vector3 force{edyn::vector3_zero};
};

template<typename Archive>
void serialize(Archive &archive, drive_input &input) {
    archive(input.force);
}

// Set by the server on each client's box. It holds the client's entity in the server's
// registry and is compared with get_network_client_entity(), which is a server entity too, so it
// is deliberately not declared in edyn::entity_members: translating it into a client entity
// would break the comparison.
struct owner {
    edyn::entity client{edyn::null};
};

template<typename Archive>
void serialize(Archive &archive, owner &o) {
    archive(o.client);
}

// Runs before every step, on the simulation worker's registry in asynchronous mode, which is
// why drive_input is registered as an external component: without it the worker never sees it.
// Sleeping bodies are skipped so that no velocity piles up while they do not move; the
// networking wakes a body when its input arrives.
inline void apply_drive(edyn::registry &registry) {
    auto dt = edyn::get_fixed_dt(registry);
    auto view = registry.view<drive_input, edyn::linvel, edyn::mass>(edyn::exclude<edyn::sleeping_tag>);
    for (auto [e, input, v, m] : view.each())
        v += input.force * (dt / m.s);
}

inline void register_components(edyn::registry &registry) {
    edyn::register_external_components<drive_input>(registry);
    edyn::register_networked_components<drive_input, owner>(registry);
    edyn::set_pre_step_callback(registry, &apply_drive);
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace example

#endif // EDYN_EXAMPLES_NETWORKING_SHARED_HPP
