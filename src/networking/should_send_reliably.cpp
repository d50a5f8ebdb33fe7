#include "edyn/networking/packet/edyn_packet.hpp"

namespace edyn {

bool should_send_reliably(const packet::edyn_packet &packet) noexcept {
    return !std::holds_alternative<packet::registry_snapshot>(packet.var) &&
           !std::holds_alternative<packet::time_request>(packet.var) &&
           !std::holds_alternative<packet::time_response>(packet.var);
}

} // namespace edyn
