#include <edyn/collision/pair_map.hpp>
#include <gtest/gtest.h>
#include <random>
#include <unordered_map>

using namespace edyn;

TEST(pair_map, finds_what_was_inserted_and_not_what_was_erased) {
    pair_map map;
    EXPECT_EQ(map.find(42), nullptr);
    EXPECT_FALSE(map.erase(42));
    map.insert_or_assign(42, 7);
    map.insert_or_assign((std::uint64_t{3} << 32) | 9, 8);
    ASSERT_NE(map.find(42), nullptr);
    EXPECT_EQ(*map.find(42), 7u);
    map.insert_or_assign(42, 11);
    EXPECT_EQ(*map.find(42), 11u);
    EXPECT_EQ(map.size(), 2u);
    EXPECT_TRUE(map.erase(42));
    EXPECT_FALSE(map.contains(42));
    EXPECT_TRUE(map.contains((std::uint64_t{3} << 32) | 9));
    map.clear();
    EXPECT_EQ(map.size(), 0u);
    EXPECT_FALSE(map.contains((std::uint64_t{3} << 32) | 9));
}

TEST(pair_map, agrees_with_a_standard_map_over_a_long_random_run) {
    // Keys from a small range, so that probe runs collide, wrap around the table's end and are
    // cut by erasures: every path of the backward shift is taken.
    std::mt19937_64 random(1234);
    std::uniform_int_distribution<std::uint64_t> key_of(0, 3000);
    std::uniform_int_distribution<int> op_of(0, 9);
    pair_map map;
    std::unordered_map<std::uint64_t, std::uint32_t> reference;
    for (std::uint32_t step = 0; step < 200000; ++step) {
        auto key = (key_of(random) << 32) | key_of(random) % 7;
        auto op = op_of(random);
        if (op < 5) {
            map.insert_or_assign(key, step);
            reference[key] = step;
        } else if (op < 9) {
            ASSERT_EQ(map.erase(key), reference.erase(key) == 1) << "step " << step;
        } else {
            auto *found = map.find(key);
            auto it = reference.find(key);
            ASSERT_EQ(found != nullptr, it != reference.end()) << "step " << step;
            if (found) {
                ASSERT_EQ(*found, it->second) << "step " << step;
            }
        }
        ASSERT_EQ(map.size(), reference.size()) << "step " << step;
    }
    for (auto &[key, value] : reference) {
        ASSERT_NE(map.find(key), nullptr);
        EXPECT_EQ(*map.find(key), value);
    }
}
