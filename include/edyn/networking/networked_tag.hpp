#ifndef EDYN_NETWORKING_NETWORKED_TAG_HPP
#define EDYN_NETWORKING_NETWORKED_TAG_HPP

#include <type_traits>

namespace edyn {

// Marks an entity (rigid body, constraint, external entity) to be shared between a server and
// its clients.
struct networked_tag {};

// Base of the components that are a client's input (a steering angle, a throttle): owned by the
// client of the entity they are on, accepted by the server only from that client, and sent in
// the next few snapshots after each change. Only idempotent state belongs in them; one-shot
// events are actions (networking/action_list.hpp).
struct network_input {};

template<typename Component>
inline constexpr bool is_network_input_v = std::is_base_of_v<network_input, Component>;

} // namespace edyn

#endif // EDYN_NETWORKING_NETWORKED_TAG_HPP
