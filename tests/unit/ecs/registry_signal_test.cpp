#include "ecs_test_support.hpp"
#include "edyn/ecs/registry.hpp"
#include <gtest/gtest.h>
#include <string>
#include <vector>

using namespace edyn;
using namespace ecs_test;

namespace {

// Records each signal with what the listener could see at that moment.
struct recorder {
    std::vector<std::string> events;

    template<typename Type>
    void watch(registry &reg, const std::string &label) {
        labels.push_back(label);
        reg.on_construct<Type>().template connect<&recorder::on<Type, 'c'>>(*this);
        reg.on_update<Type>().template connect<&recorder::on<Type, 'u'>>(*this);
        reg.on_destroy<Type>().template connect<&recorder::on<Type, 'd'>>(*this);
    }

    template<typename Type, char Kind>
    void on(registry &reg, entity e) {
        std::string text(1, Kind);
        text += ":" + std::string(type_name<Type>().substr(type_name<Type>().rfind(':') + 1));
        text += ":" + std::to_string(to_index(e));
        // What a listener sees: whether the component is there, and for position its x.
        text += reg.all_of<Type>(e) ? ":has" : ":none";
        if constexpr (std::is_same_v<Type, position>) {
            if (auto *p = reg.try_get<position>(e)) {
                text += ":" + std::to_string(int(p->x));
            }
        }
        text += reg.valid(e) ? "" : ":invalid";
        events.push_back(text);
    }

    std::vector<std::string> labels;
};

using events = std::vector<std::string>;

void on_position_construct(registry &reg, entity e) {
    // Listeners may modify the registry: tag every new position and create a companion entity.
    reg.emplace<tag>(e);
    reg.emplace<mass>(reg.create(), float(to_index(e)));
}

void on_position_destroy(registry &reg, entity e) {
    // The component is still there, and other components can be removed.
    EXPECT_TRUE(reg.all_of<position>(e));
    reg.remove<tag>(e);
}

struct destroy_linked {
    entity linked{null};
    void on(registry &reg, entity) {
        if (reg.valid(linked)) {
            reg.destroy(linked);
        }
    }
};

void readd_velocity(registry &reg, entity e) {
    // Adds a component to a pool `destroy` may already have visited: it must still go.
    if (!reg.all_of<velocity>(e)) {
        reg.emplace<velocity>(e);
    }
}

void destroy_self(registry &reg, entity e) { reg.destroy(e); }

} // namespace

TEST(registry_signal_test, emplace_fires_construct_after_the_component_is_in_place) {
    registry reg;
    recorder rec;
    rec.watch<position>(reg, "position");
    const auto e = reg.create();
    reg.emplace<position>(e, 5.f);
    EXPECT_EQ(rec.events, (events{"c:position:0:has:5"}));
    reg.get_or_emplace<position>(e, 6.f);
    EXPECT_EQ(rec.events.size(), 1u) << "get_or_emplace of a present component fires nothing";
}

TEST(registry_signal_test, update_fires_after_replace_and_patch) {
    registry reg;
    recorder rec;
    const auto e = reg.create();
    reg.emplace<position>(e, 1.f);
    rec.watch<position>(reg, "position");
    reg.replace<position>(e, 2.f);
    reg.patch<position>(e, [](position &p) { p.x = 3; });
    reg.get<position>(e).x = 4;
    reg.patch<position>(e);
    EXPECT_EQ(rec.events, (events{"u:position:0:has:2", "u:position:0:has:3", "u:position:0:has:4"}));
}

TEST(registry_signal_test, emplace_or_replace_fires_construct_then_update) {
    registry reg;
    recorder rec;
    rec.watch<position>(reg, "position");
    const auto e = reg.create();
    reg.emplace_or_replace<position>(e, 1.f);
    reg.emplace_or_replace<position>(e, 2.f);
    EXPECT_EQ(rec.events, (events{"c:position:0:has:1", "u:position:0:has:2"}));
}

TEST(registry_signal_test, remove_and_erase_fire_destroy_before_removal) {
    registry reg;
    recorder rec;
    rec.watch<position>(reg, "position");
    rec.watch<tag>(reg, "tag");
    const auto e = reg.create();
    reg.emplace<position>(e, 7.f);
    reg.emplace<tag>(e);
    rec.events.clear();
    reg.remove<position, tag>(e);
    reg.remove<position>(e);
    EXPECT_EQ(rec.events, (events{"d:position:0:has:7", "d:tag:0:has"})) << "nothing for the absent one";
    rec.events.clear();
    reg.emplace<position>(e, 8.f);
    reg.erase<position>(e);
    EXPECT_EQ(rec.events, (events{"c:position:0:has:8", "d:position:0:has:8"}));
}

TEST(registry_signal_test, clear_fires_destroy_for_each_component) {
    registry reg;
    recorder rec;
    for (int i = 0; i < 3; ++i) {
        reg.emplace<position>(reg.create(), float(i));
    }
    rec.watch<position>(reg, "position");
    reg.clear<position>();
    EXPECT_EQ(rec.events, (events{"d:position:2:has:2", "d:position:1:has:1", "d:position:0:has:0"}));
    EXPECT_EQ(reg.alive(), 3u);
    rec.events.clear();
    reg.emplace<position>(reg.create(), 9.f);
    rec.events.clear();
    reg.clear();
    EXPECT_EQ(rec.events, (events{"d:position:3:has:9"}));
    EXPECT_EQ(reg.alive(), 0u);
}

TEST(registry_signal_test, destroy_fires_for_every_component_in_reverse_pool_order_while_valid) {
    registry reg;
    recorder rec;
    // Pool creation order: position, velocity, tag.
    rec.watch<position>(reg, "position");
    rec.watch<velocity>(reg, "velocity");
    rec.watch<tag>(reg, "tag");
    const auto e = reg.create();
    reg.emplace<tag>(e);
    reg.emplace<position>(e, 3.f);
    reg.emplace<velocity>(e);
    rec.events.clear();
    reg.destroy(e);
    EXPECT_EQ(rec.events, (events{"d:tag:0:has", "d:velocity:0:has", "d:position:0:has:3"}));
    EXPECT_FALSE(reg.valid(e));
}

TEST(registry_signal_test, member_function_listeners_by_reference_and_pointer) {
    registry reg;
    recorder by_ref, by_ptr;
    reg.on_construct<position>().connect<&recorder::on<position, 'c'>>(by_ref);
    reg.on_construct<position>().connect<&recorder::on<position, 'c'>>(&by_ptr);
    reg.emplace<position>(reg.create(), 1.f);
    EXPECT_EQ(by_ref.events, (events{"c:position:0:has:1"}));
    EXPECT_EQ(by_ptr.events, by_ref.events);
    reg.on_construct<position>().disconnect(by_ref);
    reg.emplace<position>(reg.create(), 2.f);
    EXPECT_EQ(by_ref.events.size(), 1u);
    EXPECT_EQ(by_ptr.events.size(), 2u);
}

TEST(registry_signal_test, listeners_may_modify_the_registry) {
    registry reg;
    reg.on_construct<position>().connect<&on_position_construct>();
    reg.on_destroy<position>().connect<&on_position_destroy>();
    std::vector<entity> entities;
    for (int i = 0; i < 100; ++i) {
        entities.push_back(reg.create());
        auto &p = reg.emplace<position>(entities.back(), float(i));
        EXPECT_EQ(p.x, float(i)) << "emplace returns the component even after listeners changed pools";
    }
    EXPECT_EQ(reg.storage<tag>().size(), 100u);
    EXPECT_EQ(reg.storage<mass>().size(), 100u);
    EXPECT_EQ(reg.alive(), 200u);
    reg.remove<position>(entities[0]);
    EXPECT_FALSE(reg.all_of<tag>(entities[0]));
    for (std::size_t i = 1; i < entities.size(); ++i) {
        reg.destroy(entities[i]);
    }
    EXPECT_TRUE(reg.storage<tag>().empty());
    EXPECT_EQ(reg.alive(), 101u);
}

TEST(registry_signal_test, listener_may_destroy_other_entities) {
    registry reg;
    destroy_linked link;
    reg.on_destroy<position>().connect<&destroy_linked::on>(link);
    const auto a = reg.create();
    const auto b = reg.create();
    reg.emplace<position>(a);
    reg.emplace<position>(b);
    link.linked = b;
    reg.destroy(a);
    EXPECT_FALSE(reg.valid(a));
    EXPECT_FALSE(reg.valid(b));
    EXPECT_EQ(reg.alive(), 0u);
    EXPECT_TRUE(reg.storage<position>().empty());
}

TEST(registry_signal_test, components_added_by_destroy_listeners_are_removed_too) {
    registry reg;
    reg.storage<velocity>(); // velocity's pool comes first, so destroy visits it last...
    reg.on_destroy<position>().connect<&readd_velocity>();
    const auto e = reg.create();
    reg.emplace<position>(e);
    reg.destroy(e); // ...yet the listener runs after velocity was visited: a second pass is needed
    EXPECT_TRUE(reg.storage<velocity>().empty());
    EXPECT_TRUE(reg.storage<position>().empty());
    const auto reused = reg.create();
    EXPECT_EQ(to_index(reused), to_index(e));
    EXPECT_TRUE(reg.orphan(reused));
}

TEST(registry_signal_test, listener_may_destroy_the_entity_being_destroyed) {
    registry reg;
    reg.on_destroy<tag>().connect<&destroy_self>();
    const auto e = reg.create();
    reg.emplace<position>(e);
    reg.emplace<tag>(e);
    reg.destroy(e);
    EXPECT_FALSE(reg.valid(e));
    EXPECT_EQ(reg.alive(), 0u);
    const auto a = reg.create();
    const auto b = reg.create();
    EXPECT_NE(to_index(a), to_index(b)) << "the index was freed once, not twice";
}

TEST(registry_signal_test, signals_of_a_type_without_components_can_be_connected) {
    registry reg;
    recorder rec;
    rec.watch<mass>(reg, "mass");
    EXPECT_TRUE(reg.storage<mass>().empty());
    const auto e = reg.create();
    reg.emplace<mass>(e);
    reg.destroy(e);
    EXPECT_EQ(rec.events, (events{"c:mass:0:has", "d:mass:0:has"}));
}
