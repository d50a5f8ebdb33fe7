#include <edyn/edyn.hpp>
#include <edyn_scenes/scenes.hpp>
#include <gtest/gtest.h>

namespace edyn {
namespace {

// Destroying a body finds its constraints through the graph, not by scanning every constraint:
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

} // namespace
} // namespace edyn
