#ifndef EDYN_TESTS_UNIT_SERIALIZATION_SAMPLE_PACKETS_HPP
#define EDYN_TESTS_UNIT_SERIALIZATION_SAMPLE_PACKETS_HPP

// One packet of every kind with every field set to something other than its default, for the
// round-trip tests and as the seed corpus of fuzz/packet_fuzzer.cpp. A kind added to
// edyn_packet_variant without a `fill` overload here fails to compile, so it cannot be left
// out of either. Header-only and free of the registry so that the fuzzer, built by clang
// outside the main build, can include it.

#include <cstddef>
#include <edyn/networking/packet/edyn_packet.hpp>
#include <utility>
#include <variant>
#include <vector>

namespace edyn::test {

// Entities with large indices and versions, and null, so that no byte of theirs is trivially 0.
inline std::vector<entity> sample_entities() {
    return {make_entity(3, 1), make_entity(70000, 5), make_entity(entity_traits::max_entities - 1, 4095),
            null};
}

inline std::vector<packet::pool_snapshot> sample_pools() {
    return {{2, {1, 2, 3, 200}}, {513, {0, 255}}, {7, {}}};
}

inline void fill(packet::registry_snapshot &p) {
    p.timestamp = 12.5;
    p.entities = sample_entities();
    p.pools = sample_pools();
    p.inputs = {{12.75, {make_entity(9, 3)}, {{4, {0, 17, 250}}}}, {13.5, sample_entities(), sample_pools()}};
    p.removed = {{9, {0, 3}}, {600, {1}}};
}

inline void fill(packet::create_entity &p) {
    p.timestamp = 3.25;
    p.entities = sample_entities();
    p.pools = sample_pools();
}

inline void fill(packet::destroy_entity &p) {
    p.timestamp = 100.125;
    p.entities = sample_entities();
}

inline void fill(packet::entity_entered &p) {
    p.assets = {
        {make_entity(11, 2), 0x0123456789abcdefULL, {{0, make_entity(12, 2)}, {7, make_entity(13, 3)}}},
        {make_entity(21, 0), 42, {}}};
}

inline void fill(packet::entity_exited &p) { p.entities = sample_entities(); }

inline void fill(packet::entity_request &p) { p.entities = {make_entity(99, 9)}; }

inline void fill(packet::asset_sync &p) { p.asset_entity = make_entity(5, 6); }

inline void fill(packet::asset_sync_response &p) {
    p.timestamp = 7.75;
    p.asset_entity = make_entity(8, 1);
    p.entities = sample_entities();
    p.pools = sample_pools();
}

inline void fill(packet::time_request &p) { p.id = 0xdeadbeef; }

inline void fill(packet::time_response &p) {
    p.id = 77;
    p.timestamp = 1234.5;
}

inline void fill(packet::server_settings &p) {
    p.fixed_dt = scalar(1) / 60;
    p.gravity = {scalar(0.5), scalar(-9.81), scalar(0.25)};
    p.num_substeps = 4;
    p.num_relax_iterations = 3;
    p.num_restitution_iterations = 8;
    p.num_individual_restitution_iterations = 10;
    p.max_linear_speed = 250;
    p.contact = {61, 31, scalar(1.5), scalar(0.2), 2, scalar(0.4)};
    p.joint = {59, scalar(0.9), scalar(0.3), scalar(0.2), scalar(0.8), 5, scalar(0.07), 4};
}

inline void fill(packet::set_playout_delay &p) { p.value = 0.15; }

inline void fill(packet::client_created &p) { p.client_entity = make_entity(4, 2); }

template<std::size_t Index>
packet::edyn_packet sample_packet() {
    packet::edyn_packet packet;
    fill(packet.var.template emplace<Index>());
    return packet;
}

// sample_packet<I>() for every I, in the variant's order.
inline std::vector<packet::edyn_packet> sample_packets() {
    return []<std::size_t... Is>(std::index_sequence<Is...>) {
        return std::vector<packet::edyn_packet>{sample_packet<Is>()...};
    }
    (std::make_index_sequence<std::variant_size_v<packet::edyn_packet_variant>>{});
}

} // namespace edyn::test

#endif // EDYN_TESTS_UNIT_SERIALIZATION_SAMPLE_PACKETS_HPP
