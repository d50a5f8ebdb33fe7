#include <edyn/edyn.hpp>
#include <edyn_scenes/scenes.hpp>
#include <gtest/gtest.h>

namespace edyn {
namespace {

// Destroying a body finds its constraints through its own list, not by scanning every constraint:
// a large scene built and cleared body by body finishes, and nothing of it is left behind.
TEST(registry_listeners, a_chain_of_ten_thousand_links_is_destroyed_with_its_joints) {
    registry reg;
    attach(reg);
    constexpr unsigned links = 10'000;
    auto chain = scenes::make_chain(reg, links);
    ASSERT_EQ(chain.joints.size(), links);
    EXPECT_EQ(reg.storage<point_constraint>().size(), links);
    EXPECT_EQ(reg.storage<island>().size(), 1u) << "the joints put every link in one island";

    for (auto link : chain.links)
        reg.destroy(link);

    EXPECT_EQ(reg.storage<point_constraint>().size(), 0u);
    std::size_t left = 0;
    for (auto joint : chain.joints)
        left += reg.valid(joint);
    EXPECT_EQ(left, 0u) << "joint entities outlived their links";
    EXPECT_EQ(reg.storage<island>().size(), 0u);
    EXPECT_EQ(reg.storage<island_resident>().size(), 0u);
    EXPECT_TRUE(reg.valid(chain.anchor));
}

// A constraint between bodies that are not dynamic has no island; it joins one when one of its
// bodies turns dynamic, and goes when either body goes, dynamic or not.
TEST(registry_listeners, a_joint_joins_an_island_when_its_body_turns_dynamic) {
    registry reg;
    attach(reg);
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    auto anchor = make_rigidbody(reg, def);
    def.kind = rigidbody_kind::rb_kinematic;
    def.position = {1, 0, 0};
    def.shape = sphere_shape{scalar(0.5)};
    auto body = make_rigidbody(reg, def);
    auto joint = make_constraint<point_constraint>(reg, anchor, body);
    EXPECT_FALSE(reg.all_of<island_resident>(joint));

    rigidbody_set_kind(reg, body, rigidbody_kind::rb_dynamic);
    ASSERT_TRUE(reg.all_of<island_resident>(joint));
    EXPECT_EQ(reg.get<island_resident>(joint).island_entity, reg.get<island_resident>(body).island_entity);

    reg.destroy(anchor);
    EXPECT_FALSE(reg.valid(joint));
    EXPECT_TRUE(reg.valid(body));
}

} // namespace
} // namespace edyn
