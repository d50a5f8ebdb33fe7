#include "ecs_test_support.hpp"
#include "edyn/ecs/entity.hpp"
#include "edyn/ecs/entity_map.hpp"
#include "edyn/ecs/fwd.hpp"
#include "edyn/ecs/type_info.hpp"
#include <gtest/gtest.h>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

using namespace edyn;

static_assert(std::is_same_v<std::underlying_type_t<entity>, std::uint32_t>);
static_assert(sizeof(entity) == 4);

TEST(entity_test, traits_split_twenty_and_twelve_bits) {
    EXPECT_EQ(entity_traits::index_bits, 20u);
    EXPECT_EQ(entity_traits::version_bits, 12u);
    EXPECT_EQ(entity_traits::index_mask, 0xFFFFFu);
    EXPECT_EQ(entity_traits::version_mask, 0xFFFu);
}

TEST(entity_test, make_entity_round_trips_index_and_version) {
    for (std::uint32_t index : {0u, 1u, 5u, 4095u, 4096u, 0xFFFFEu}) {
        for (std::uint32_t version : {0u, 1u, 7u, 0xFFFu}) {
            const auto e = make_entity(index, version);
            EXPECT_EQ(to_index(e), index) << "version " << version;
            EXPECT_EQ(to_entity(e), index);
            EXPECT_EQ(to_version(e), version) << "index " << index;
            EXPECT_EQ(to_integral(e), index | (version << 20));
        }
    }
}

TEST(entity_test, make_entity_wraps_versions_past_twelve_bits) {
    EXPECT_EQ(to_version(make_entity(3, 0x1000)), 0u);
    EXPECT_EQ(to_version(make_entity(3, 0x1001)), 1u);
    EXPECT_EQ(to_index(make_entity(3, 0x1001)), 3u);
}

TEST(entity_test, null_converts_and_compares) {
    entity e = null;
    EXPECT_TRUE(e == null);
    EXPECT_TRUE(null == e);
    EXPECT_FALSE(e != null);
    EXPECT_EQ(to_index(e), entity_traits::index_mask);
    EXPECT_TRUE(null == null);

    const auto real = make_entity(5, 2);
    EXPECT_TRUE(real != null);
    EXPECT_TRUE(null != real);
    EXPECT_FALSE(real == null);
    EXPECT_TRUE(entity{} != null) << "a value-initialized entity is index 0, not null";

    // Like EnTT's, null ignores the version.
    EXPECT_TRUE(make_entity(entity_traits::index_mask, 3) == null);
}

TEST(entity_test, null_is_usable_in_constant_expressions) {
    constexpr entity e = null;
    static_assert(e == null);
    static_assert(make_entity(1, 0) != null);
    SUCCEED();
}

TEST(entity_test, std_hash_and_ordering_work) {
    std::unordered_set<entity> hashed;
    std::set<entity> ordered;
    for (std::uint32_t i = 0; i < 100; ++i) {
        hashed.insert(make_entity(i, i % 3));
        ordered.insert(make_entity(i, i % 3));
    }
    hashed.insert(make_entity(7, 1));
    EXPECT_EQ(hashed.size(), 100u);
    EXPECT_EQ(ordered.size(), 100u);
    EXPECT_TRUE(hashed.count(make_entity(7, 1)));
    EXPECT_FALSE(hashed.count(make_entity(7, 2)));
    EXPECT_EQ(std::hash<entity>{}(make_entity(9, 0)), std::hash<entity>{}(make_entity(9, 0)));
}

namespace ecs_test::detail_names {
template<typename T>
struct wrapper {};
} // namespace ecs_test::detail_names

TEST(entity_map_test, insert_refuses_a_null_source) {
    entity_map map;
    auto source = make_entity(3, 1), target = make_entity(7, 0);
    map.insert(source, target);
    try {
        map.insert(null, target);
        ADD_FAILURE() << "expected std::invalid_argument for a null source";
    } catch (const std::invalid_argument &e) {
        std::string what = e.what();
        EXPECT_NE(what.find("entity_map::insert"), std::string::npos) << what;
        EXPECT_NE(what.find("null"), std::string::npos) << what;
    }
    EXPECT_EQ(map.find(source), target) << "the map is left as it was";
    EXPECT_EQ(map.find(null), null);
}

TEST(entity_map_test, source_at_names_the_version_mapped_at_an_index) {
    entity_map map;
    auto earlier = make_entity(3, 1), later = make_entity(3, 2), target = make_entity(7, 0);
    EXPECT_EQ(map.source_at(earlier), null) << "nothing mapped yet";
    map.insert(earlier, target);
    EXPECT_EQ(map.source_at(earlier), earlier);
    EXPECT_EQ(map.source_at(later), earlier) << "another version at the same index";
    EXPECT_EQ(map.find(later), null);
    EXPECT_EQ(map.source_at(make_entity(4, 1)), null) << "another index";
    EXPECT_EQ(map.source_at(make_entity(100, 0)), null) << "an index past the map's end";
    map.erase(earlier);
    EXPECT_EQ(map.source_at(earlier), null);
}

TEST(type_info_test, type_name_spells_qualified_names) {
    EXPECT_EQ(type_name<ecs_test::position>(), "ecs_test::position");
    EXPECT_EQ(type_name<int>(), "int");
    EXPECT_EQ(type_name<entity>(), "edyn::entity");
    const auto templated = std::string(type_name<ecs_test::detail_names::wrapper<int>>());
    EXPECT_EQ(templated, "ecs_test::detail_names::wrapper<int>");
    const auto vector_name = std::string(type_name<std::vector<int>>());
    EXPECT_NE(vector_name.find("std::vector<int"), std::string::npos) << vector_name;
}

TEST(type_info_test, type_name_is_constexpr) {
    constexpr auto name = type_name<ecs_test::velocity>();
    static_assert(name == "ecs_test::velocity");
    SUCCEED();
}

TEST(type_info_test, type_index_is_dense_stable_and_ignores_qualifiers) {
    const auto a = type_index<ecs_test::position>();
    const auto b = type_index<ecs_test::velocity>();
    const auto c = type_index<ecs_test::mass>();
    EXPECT_NE(a, b);
    EXPECT_NE(b, c);
    EXPECT_NE(a, c);
    EXPECT_EQ(a, type_index<ecs_test::position>());
    EXPECT_EQ(a, type_index<const ecs_test::position>());
    EXPECT_EQ(a, type_index<ecs_test::position &>());
    EXPECT_EQ(a, type_index<const ecs_test::position &>());
    // Dense: every id ever handed out is below the number of types used by this program,
    // which is far fewer than a thousand.
    EXPECT_LT(std::max({a, b, c}), 1000u);
}
