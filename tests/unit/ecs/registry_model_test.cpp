#include "ecs_test_support.hpp"
#include "edyn/ecs/registry.hpp"
#include <gtest/gtest.h>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace edyn;
using namespace ecs_test;

namespace {

// The model: for each entity alive, its optional position.x, optional mass, and tag flag.
struct model_entry {
    std::optional<float> x;
    std::optional<float> m;
    bool tagged{false};
};

struct counters {
    int constructs{0};
    int updates{0};
    int destroys{0};
    void construct(registry &, entity) { ++constructs; }
    void update(registry &, entity) { ++updates; }
    void destroy(registry &, entity) { ++destroys; }
};

void check_against_model(const registry &reg, const std::map<entity, model_entry> &model, int step) {
    ASSERT_EQ(reg.alive(), model.size()) << "step " << step;
    std::size_t positions = 0, masses = 0, tags = 0;
    for (const auto &[e, entry] : model) {
        ASSERT_TRUE(reg.valid(e)) << "step " << step << " entity " << to_index(e);
        ASSERT_EQ(reg.all_of<position>(e), entry.x.has_value()) << "step " << step;
        ASSERT_EQ(reg.all_of<mass>(e), entry.m.has_value()) << "step " << step;
        ASSERT_EQ(reg.all_of<tag>(e), entry.tagged) << "step " << step;
        if (entry.x) {
            ASSERT_EQ(reg.get<position>(e).x, *entry.x) << "step " << step;
            ++positions;
        }
        if (entry.m) {
            ASSERT_EQ(reg.get<mass>(e).value, *entry.m) << "step " << step;
            ++masses;
        }
        tags += entry.tagged;
        ASSERT_EQ(reg.orphan(e), !entry.x && !entry.m && !entry.tagged) << "step " << step;
    }
    ASSERT_EQ(reg.storage<position>().size(), positions) << "step " << step;
    ASSERT_EQ(reg.storage<mass>().size(), masses) << "step " << step;
    ASSERT_EQ(reg.storage<tag>().size(), tags) << "step " << step;

    // Views agree with the model too.
    std::set<entity> in_view;
    reg.view<position, mass>(exclude<tag>).each([&](entity e, const position &p, const mass &m) {
        in_view.insert(e);
        ASSERT_EQ(p.x, *model.at(e).x);
        ASSERT_EQ(m.value, *model.at(e).m);
    });
    std::set<entity> expected;
    for (const auto &[e, entry] : model) {
        if (entry.x && entry.m && !entry.tagged) {
            expected.insert(e);
        }
    }
    ASSERT_EQ(in_view, expected) << "step " << step;
}

} // namespace

TEST(registry_model_test, random_operations_match_a_map_model) {
    registry reg;
    counters count;
    reg.on_construct<position>().connect<&counters::construct>(count);
    reg.on_update<position>().connect<&counters::update>(count);
    reg.on_destroy<position>().connect<&counters::destroy>(count);
    int expected_constructs = 0, expected_updates = 0, expected_destroys = 0;

    std::map<entity, model_entry> model;
    std::vector<entity> dead;
    std::mt19937 rng(12345);
    auto pick = [&]() -> entity {
        auto it = model.begin();
        std::advance(it, std::uniform_int_distribution<std::size_t>(0, model.size() - 1)(rng));
        return it->first;
    };

    constexpr int steps = 20000;
    for (int step = 0; step < steps; ++step) {
        const int op = std::uniform_int_distribution<int>(0, 11)(rng);
        const float value = float(step);
        if (model.empty() || op == 0 || op == 1) {
            entity e;
            if (!dead.empty() && op == 1) {
                // A hinted create of a dead handle's index with a fresh version.
                const auto stale = dead[std::uniform_int_distribution<std::size_t>(0, dead.size() - 1)(rng)];
                const auto hint = make_entity(to_index(stale), to_version(stale) + 7);
                e = reg.create(hint);
                if (model.count(hint) == 0 && !reg.valid(stale)) {
                    bool index_taken = false;
                    for (const auto &[alive, entry] : model) {
                        index_taken |= to_index(alive) == to_index(hint);
                    }
                    if (!index_taken) {
                        ASSERT_EQ(e, hint) << "step " << step;
                    }
                }
            } else {
                e = reg.create();
            }
            ASSERT_EQ(model.count(e), 0u) << "step " << step << ": created an entity that is alive";
            model[e] = {};
            continue;
        }
        const auto e = pick();
        auto &entry = model[e];
        switch (op) {
        case 2:
            if (entry.x) {
                EXPECT_THROW(reg.emplace<position>(e, value), std::invalid_argument);
            } else {
                reg.emplace<position>(e, value);
                entry.x = value;
                ++expected_constructs;
            }
            break;
        case 3:
            if (entry.x) {
                ++expected_updates;
            } else {
                ++expected_constructs;
            }
            reg.emplace_or_replace<position>(e, value);
            entry.x = value;
            break;
        case 4:
            if (entry.x) {
                reg.patch<position>(e, [value](position &p) { p.x = value; });
                entry.x = value;
                ++expected_updates;
            }
            break;
        case 5: {
            const auto removed = reg.remove<position, mass>(e);
            ASSERT_EQ(removed, std::size_t(entry.x.has_value()) + std::size_t(entry.m.has_value()));
            expected_destroys += entry.x.has_value();
            entry.x.reset();
            entry.m.reset();
            break;
        }
        case 6:
            reg.emplace_or_replace<mass>(e, value);
            entry.m = value;
            break;
        case 7:
            if (entry.tagged) {
                reg.erase<tag>(e);
            } else {
                reg.emplace<tag>(e);
            }
            entry.tagged = !entry.tagged;
            break;
        case 8:
        case 9:
            expected_destroys += entry.x.has_value();
            reg.destroy(e);
            dead.push_back(e);
            model.erase(e);
            ASSERT_FALSE(reg.valid(e));
            break;
        case 10:
            if (entry.m) {
                reg.replace<mass>(e, value);
                entry.m = value;
            }
            break;
        default:
            if (step % 997 == 0) {
                expected_destroys += int(reg.storage<position>().size());
                reg.clear<position>();
                for (auto &[alive, other] : model) {
                    other.x.reset();
                }
            }
            break;
        }
        if (step % 500 == 0) {
            check_against_model(reg, model, step);
            for (auto stale : dead) {
                if (model.count(stale) == 0) {
                    ASSERT_FALSE(reg.valid(stale)) << "step " << step;
                    ASSERT_EQ(reg.try_get<position>(stale), nullptr);
                }
            }
        }
    }
    check_against_model(reg, model, steps);
    EXPECT_EQ(count.constructs, expected_constructs);
    EXPECT_EQ(count.updates, expected_updates);
    EXPECT_EQ(count.destroys, expected_destroys);
    EXPECT_GT(expected_constructs, 1000) << "the random walk exercised the signals";
}
