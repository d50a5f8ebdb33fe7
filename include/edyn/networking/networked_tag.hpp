#ifndef EDYN_NETWORKING_NETWORKED_TAG_HPP
#define EDYN_NETWORKING_NETWORKED_TAG_HPP

#include <type_traits>

namespace edyn {

/// Marks an entity (rigid body, constraint, external entity) to be shared between a server and
/// its clients. The program emplaces it on the server's entities; a client's engine puts it on the
/// entities it makes for the server's.
struct networked_tag {};

/// Base of the components that are a client's input (a steering angle, a throttle).
///
/// Such components are owned by the client of the entity they are on (remote_client::owned_entities),
/// accepted by the server only from that client, and sent in the next few snapshots after each
/// change. Only idempotent state belongs in them; one-shot events are actions
/// (networking/action_list.hpp).
struct network_input {};

/// Whether `Component` is a client's input, that is, derives from network_input.
template<typename Component>
inline constexpr bool is_network_input_v = std::is_base_of_v<network_input, Component>;

} // namespace edyn

#endif // EDYN_NETWORKING_NETWORKED_TAG_HPP
