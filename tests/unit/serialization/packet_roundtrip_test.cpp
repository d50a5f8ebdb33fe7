// Every kind of edyn_packet through the memory archives: filled, encoded, decoded and compared
// field by field; truncated and padded encodings; and which kinds travel reliably.
#include "unit/serialization/sample_packets.hpp"
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <edyn/networking/packet/edyn_packet.hpp>
#include <edyn/serialization/memory_archive.hpp>
#include <gtest/gtest.h>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

using namespace edyn;

namespace {

constexpr auto packet_kinds = std::variant_size_v<packet::edyn_packet_variant>;

// The members of each packet, for comparisons. A new kind needs an overload here too, or the
// round-trip test does not compile.
auto fields(const packet::pool_snapshot &p) { return std::tie(p.component_index, p.data); }
auto fields(const packet::entered_asset &p) { return std::tie(p.asset_entity, p.id, p.members); }
auto fields(const packet::timed_inputs &p) { return std::tie(p.timestamp, p.entities, p.pools); }
auto fields(const packet::registry_snapshot &p) {
    return std::tie(p.timestamp, p.entities, p.pools, p.inputs, p.removed);
}
auto fields(const packet::create_entity &p) { return std::tie(p.timestamp, p.entities, p.pools); }
auto fields(const packet::destroy_entity &p) { return std::tie(p.timestamp, p.entities); }
auto fields(const packet::entity_entered &p) { return std::tie(p.assets); }
auto fields(const packet::entity_exited &p) { return std::tie(p.entities); }
auto fields(const packet::entity_request &p) { return std::tie(p.entities); }
auto fields(const packet::asset_sync &p) { return std::tie(p.asset_entity); }
auto fields(const packet::asset_sync_response &p) {
    return std::tie(p.timestamp, p.asset_entity, p.entities, p.pools);
}
auto fields(const packet::time_request &p) { return std::tie(p.id); }
auto fields(const packet::time_response &p) { return std::tie(p.id, p.timestamp); }
auto fields(const packet::server_settings &p) {
    return std::tie(p.fixed_dt, p.gravity, p.num_substeps, p.num_relax_iterations,
                    p.num_restitution_iterations, p.num_individual_restitution_iterations, p.max_linear_speed,
                    p.contact, p.joint);
}
auto fields(const packet::set_playout_delay &p) { return std::tie(p.value); }
auto fields(const packet::client_created &p) { return std::tie(p.client_entity); }

template<typename T>
struct is_vector : std::false_type {};
template<typename T>
struct is_vector<std::vector<T>> : std::true_type {};

template<typename T>
bool same(const T &a, const T &b) {
    if constexpr (requires { fields(a); }) {
        auto fa = fields(a);
        auto fb = fields(b);
        return [&]<std::size_t... Is>(std::index_sequence<Is...>) {
            return (same(std::get<Is>(fa), std::get<Is>(fb)) && ...);
        }
        (std::make_index_sequence<std::tuple_size_v<decltype(fa)>>{});
    } else if constexpr (is_vector<T>::value) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (!same(a[i], b[i])) return false;
        }
        return true;
    } else {
        return a == b;
    }
}

// The index of the first member equal to its default, or -1: the samples must set every field
// so that a field dropped by a serialize function shows in the comparison.
template<typename T>
int first_default_field(const T &value) {
    T defaults{};
    auto fv = fields(value);
    auto fd = fields(defaults);
    int found = -1;
    [&]<std::size_t... Is>(std::index_sequence<Is...>) {
        ((found < 0 && same(std::get<Is>(fv), std::get<Is>(fd)) ? void(found = int(Is)) : void()), ...);
    }
    (std::make_index_sequence<std::tuple_size_v<decltype(fv)>>{});
    return found;
}

std::vector<std::uint8_t> encode_packet(const packet::edyn_packet &packet) {
    std::vector<std::uint8_t> data;
    memory_output_archive archive(data);
    archive(packet);
    return data;
}

// Decodes from a heap block of exactly `size` bytes, so that AddressSanitizer sees over-reads.
bool decode_packet(const std::uint8_t *bytes, std::size_t size, packet::edyn_packet &packet,
                   std::size_t *left = nullptr) {
    // The range constructor allocates exactly `size` bytes.
    auto block = std::vector<std::uint8_t>(bytes, bytes + size);
    memory_input_archive archive(block.data(), block.size());
    archive(packet);
    if (left) *left = archive.remaining();
    return !archive.failed();
}

template<std::size_t Index>
void check_round_trip() {
    using kind = std::variant_alternative_t<Index, packet::edyn_packet_variant>;
    auto sample = test::sample_packet<Index>();
    auto &original = std::get<Index>(sample.var);
    EXPECT_EQ(first_default_field(original), -1)
        << "sample of kind " << Index << " leaves a field at its default";

    auto data = encode_packet(sample);
    ASSERT_FALSE(data.empty());
    EXPECT_EQ(data[0], Index) << "the first byte is the kind";
    EXPECT_NE(data, encode_packet(packet::edyn_packet{kind{}})) << "kind " << Index;

    packet::edyn_packet decoded;
    std::size_t left = 1;
    ASSERT_TRUE(decode_packet(data.data(), data.size(), decoded, &left)) << "kind " << Index;
    EXPECT_EQ(left, 0u) << "kind " << Index;
    ASSERT_EQ(decoded.var.index(), Index);
    EXPECT_TRUE(same(std::get<Index>(decoded.var), original))
        << "kind " << Index << " changed in the round trip";
    EXPECT_EQ(encode_packet(decoded), data) << "kind " << Index << " re-encodes differently";

    // Every strict prefix fails without reading past it.
    for (std::size_t size = 0; size < data.size(); ++size) {
        packet::edyn_packet truncated;
        EXPECT_FALSE(decode_packet(data.data(), size, truncated))
            << "kind " << Index << ", " << size << " of " << data.size() << " bytes";
    }

    // Bytes after a packet are not part of it: the archive leaves them for the caller.
    auto padded = data;
    padded.insert(padded.end(), {0xff, 0x00, 0x7f});
    packet::edyn_packet with_trailing;
    ASSERT_TRUE(decode_packet(padded.data(), padded.size(), with_trailing, &left)) << "kind " << Index;
    EXPECT_EQ(left, 3u) << "kind " << Index;
    EXPECT_EQ(encode_packet(with_trailing), data) << "kind " << Index;
}

TEST(packet_roundtrip, every_kind) {
    [&]<std::size_t... Is>(std::index_sequence<Is...>) { (check_round_trip<Is>(), ...); }
    (std::make_index_sequence<packet_kinds>{});
}

TEST(packet_roundtrip, registry_snapshot_fields) {
    auto data = encode_packet(test::sample_packet<0>());
    packet::edyn_packet decoded;
    ASSERT_TRUE(decode_packet(data.data(), data.size(), decoded));
    auto *snapshot = std::get_if<packet::registry_snapshot>(&decoded.var);
    ASSERT_NE(snapshot, nullptr);
    EXPECT_EQ(snapshot->timestamp, 12.5);
    ASSERT_EQ(snapshot->entities.size(), 4u);
    EXPECT_EQ(snapshot->entities[1], make_entity(70000, 5));
    EXPECT_TRUE(snapshot->entities[3] == null);
    ASSERT_EQ(snapshot->pools.size(), 3u);
    EXPECT_EQ(snapshot->pools[1].component_index, 513);
    EXPECT_EQ(snapshot->pools[0].data, (std::vector<std::uint8_t>{1, 2, 3, 200}));
    EXPECT_TRUE(snapshot->pools[2].data.empty());
    ASSERT_EQ(snapshot->inputs.size(), 2u);
    EXPECT_EQ(snapshot->inputs[0].timestamp, 12.75);
    EXPECT_EQ(snapshot->inputs[0].entities, (std::vector<entity>{make_entity(9, 3)}));
    ASSERT_EQ(snapshot->inputs[0].pools.size(), 1u);
    EXPECT_EQ(snapshot->inputs[0].pools[0].component_index, 4);
    EXPECT_EQ(snapshot->inputs[1].pools.size(), 3u);
    ASSERT_EQ(snapshot->removed.size(), 2u);
    EXPECT_EQ(snapshot->removed[1].component_index, 600);
    EXPECT_EQ(snapshot->removed[0].data, (std::vector<std::uint8_t>{0, 3}));
}

TEST(packet_roundtrip, settings_and_assets_fields) {
    auto settings_packet = packet::edyn_packet{};
    test::fill(settings_packet.var.emplace<packet::server_settings>());
    auto data = encode_packet(settings_packet);
    packet::edyn_packet decoded;
    ASSERT_TRUE(decode_packet(data.data(), data.size(), decoded));
    auto &settings = std::get<packet::server_settings>(decoded.var);
    EXPECT_EQ(settings.fixed_dt, scalar(1) / 60);
    EXPECT_EQ(settings.gravity, (vector3{scalar(0.5), scalar(-9.81), scalar(0.25)}));
    EXPECT_EQ(settings.num_individual_restitution_iterations, 10u);

    auto assets_packet = packet::edyn_packet{};
    test::fill(assets_packet.var.emplace<packet::entity_entered>());
    data = encode_packet(assets_packet);
    ASSERT_TRUE(decode_packet(data.data(), data.size(), decoded));
    auto &entered = std::get<packet::entity_entered>(decoded.var);
    ASSERT_EQ(entered.assets.size(), 2u);
    EXPECT_EQ(entered.assets[0].id, 0x0123456789abcdefULL);
    ASSERT_EQ(entered.assets[0].members.size(), 2u);
    EXPECT_EQ(entered.assets[0].members[1].first, 7u);
    EXPECT_EQ(entered.assets[0].members[1].second, make_entity(13, 3));
    EXPECT_TRUE(entered.assets[1].members.empty());
}

TEST(packet_roundtrip, small_packets_have_the_expected_bytes) {
    auto packet = packet::edyn_packet{packet::time_request{0xdeadbeef}};
    auto index = std::uint8_t(packet.var.index());
    EXPECT_EQ(encode_packet(packet), (std::vector<std::uint8_t>{index, 0xef, 0xbe, 0xad, 0xde}));
}

TEST(packet_roundtrip, unknown_kind_fails) {
    for (std::size_t kind : {packet_kinds, std::size_t{255}}) {
        std::vector<std::uint8_t> data{std::uint8_t(kind), 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
        packet::edyn_packet decoded{packet::time_request{5}};
        EXPECT_FALSE(decode_packet(data.data(), data.size(), decoded)) << "kind " << kind;
        ASSERT_TRUE(std::holds_alternative<packet::time_request>(decoded.var));
        EXPECT_EQ(std::get<packet::time_request>(decoded.var).id, 5u) << "a failed decode changed the packet";
    }
}

TEST(packet_roundtrip, reliability_of_each_kind) {
    auto samples = test::sample_packets();
    ASSERT_EQ(samples.size(), packet_kinds);
    for (auto &sample : samples) {
        // Snapshots and the clock's messages are repeated; everything else must arrive.
        auto expected = !std::holds_alternative<packet::registry_snapshot>(sample.var) &&
                        !std::holds_alternative<packet::time_request>(sample.var) &&
                        !std::holds_alternative<packet::time_response>(sample.var);
        EXPECT_EQ(should_send_reliably(sample), expected) << "kind " << sample.var.index();
    }
    EXPECT_FALSE(should_send_reliably(packet::edyn_packet{packet::registry_snapshot{}}));
    EXPECT_FALSE(should_send_reliably(packet::edyn_packet{packet::time_request{}}));
    EXPECT_FALSE(should_send_reliably(packet::edyn_packet{packet::time_response{}}));
    EXPECT_TRUE(should_send_reliably(packet::edyn_packet{packet::create_entity{}}));
    EXPECT_TRUE(should_send_reliably(packet::edyn_packet{packet::client_created{}}));
}

} // namespace
