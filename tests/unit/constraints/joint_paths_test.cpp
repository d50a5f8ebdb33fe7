#include <cstring>
#include <edyn/constraints/joint_paths.hpp>
#include <edyn/parallel/task_scheduler.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <vector>

using namespace edyn;

namespace {

// Solver bodies and the anchors of the joints between them, built by hand: body 0 is the static
// body, the others move.
struct joint_world {
    std::vector<solver_body> bodies;
    std::vector<std::unique_ptr<joint_anchor>> anchors;
    std::vector<joint_anchor *> pivots;
    std::vector<solver_body_index> others;
    joint_path_set paths;

    explicit joint_world(std::size_t num_bodies)
        : bodies(num_bodies) {
        for (std::size_t i = 1; i < num_bodies; ++i) {
            bodies[i].inv_mass = 1;
            // A 0.5 m by 0.1 m by 0.1 m rod of 1 kg along x.
            bodies[i].inv_inertia = diagonal_matrix(
                {scalar(1) / scalar(0.00167), scalar(1) / scalar(0.0217), scalar(1) / scalar(0.0217)});
        }
    }

    // A joint between a and b, its pivots at the lever arms rA and rB, `gap` apart (pivot A
    // minus pivot B).
    joint_anchor *join(solver_body_index a, solver_body_index b, vector3 rA, vector3 rB,
                       vector3 gap = vector3_zero) {
        auto anchor = std::make_unique<joint_anchor>();
        anchor->body[0] = a;
        anchor->body[1] = b;
        anchor->rA = rA;
        anchor->rB = rB;
        anchor->separation = gap;
        pivots.push_back(anchor.get());
        anchors.push_back(std::move(anchor));
        return pivots.back();
    }

    void build() { build_joint_paths(paths, pivots, others, bodies); }

    std::size_t num_paths() const { return paths.path_begin.size() - 1; }

    // The anchors of the path holding `anchor`, in the path's order.
    std::vector<joint_anchor *> path_of(const joint_anchor *anchor) const {
        for (std::size_t p = 0; p + 1 < paths.path_begin.size(); ++p) {
            std::vector<joint_anchor *> path(paths.anchors.begin() + paths.path_begin[p],
                                             paths.anchors.begin() + paths.path_begin[p + 1]);
            if (std::find(path.begin(), path.end(), anchor) != path.end()) return path;
        }
        return {};
    }

    scalar worst_separation() const {
        scalar worst = 0;
        for (auto *anchor : pivots)
            worst = std::max(
                worst, length(current_pose(*anchor, bodies[anchor->body[0]], bodies[anchor->body[1]]).d));
        return worst;
    }
};

const scalar half = scalar(0.25);
const vector3 ahead{half, 0, 0}, behind{-half, 0, 0};

// A chain of `links` rods hanging from the static body, each joint `gap` open.
joint_world make_chain(unsigned links, vector3 gap) {
    joint_world world(links + 1);
    world.join(0, 1, vector3_zero, behind, gap);
    for (solver_body_index i = 1; i < links; ++i)
        world.join(i, i + 1, ahead, behind, gap);
    return world;
}

// Turns each rod's inverse inertia by a different rotation, so that no entry of it is zero.
void turn_rods(joint_world &world) {
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        auto axis = normalize(vector3{1, scalar(i % 3), scalar(0.5) + scalar(i % 5)});
        auto r = to_matrix3x3(quaternion_axis_angle(axis, scalar(0.3) * scalar(i)));
        world.bodies[i].inv_inertia = r * world.bodies[i].inv_inertia * transpose(r);
    }
}

} // namespace

TEST(joint_paths, a_hanging_chain_is_one_path_in_its_order) {
    auto world = make_chain(10, vector3_zero);
    world.build();
    ASSERT_EQ(world.num_paths(), 1u);
    EXPECT_EQ(world.path_of(world.pivots[0]), world.pivots);
    EXPECT_TRUE(world.paths.isolated[0]) << "it meets nothing: one end is the world, the other free";
}

TEST(joint_paths, joints_given_in_any_order_or_direction_make_the_same_path) {
    joint_world world(6);
    // A chain 0-1-2-3-4-5, its joints listed out of order and some turned round.
    auto j34 = world.join(4, 3, behind, ahead);
    auto j01 = world.join(0, 1, vector3_zero, behind);
    auto j23 = world.join(2, 3, ahead, behind);
    auto j12 = world.join(2, 1, behind, ahead);
    auto j45 = world.join(4, 5, ahead, behind);
    world.build();
    ASSERT_EQ(world.num_paths(), 1u);
    auto path = world.path_of(j01);
    ASSERT_EQ(path.size(), 5u);
    // Whichever end it starts from, the joints follow one another along the chain.
    std::vector<joint_anchor *> forward{j01, j12, j23, j34, j45}, backward{j45, j34, j23, j12, j01};
    EXPECT_TRUE(path == forward || path == backward);
}

TEST(joint_paths, a_body_with_three_joints_ends_the_paths_that_meet_there) {
    // A Y: body 1 holds three arms of two rods each.
    joint_world world(8);
    std::vector<joint_anchor *> arms[3];
    for (solver_body_index arm = 0; arm < 3; ++arm) {
        auto first = 2 + 2 * arm;
        arms[arm].push_back(world.join(1, first, ahead, behind));
        arms[arm].push_back(world.join(first, first + 1, ahead, behind));
    }
    world.build();
    EXPECT_EQ(world.num_paths(), 3u);
    for (auto &arm : arms) {
        auto path = world.path_of(arm[0]);
        EXPECT_EQ(path.size(), 2u);
        EXPECT_NE(std::find(path.begin(), path.end(), arm[1]), path.end());
    }
    for (std::size_t p = 0; p < world.num_paths(); ++p)
        EXPECT_FALSE(world.paths.isolated[p]) << "path " << p << " meets the others at body 1";
    // They share body 1: one colour each, in the order found.
    EXPECT_EQ(world.paths.colour_block_begin.size(), 4u);
}

TEST(joint_paths, another_projected_joint_on_a_body_ends_the_path_there) {
    auto world = make_chain(6, vector3_zero);
    // A distance joint on body 3 (its other end on the world).
    world.others = {3, 0};
    world.build();
    ASSERT_EQ(world.num_paths(), 2u);
    EXPECT_EQ(world.path_of(world.pivots[0]).size(), 3u);
    EXPECT_EQ(world.path_of(world.pivots[5]).size(), 3u);
}

TEST(joint_paths, a_ring_of_links_is_opened_into_one_path) {
    joint_world world(5);
    for (solver_body_index i = 1; i <= 4; ++i)
        world.join(i, i % 4 + 1, ahead, behind);
    world.build();
    ASSERT_EQ(world.num_paths(), 1u);
    EXPECT_EQ(world.path_of(world.pivots[0]).size(), 4u);
}

// The reason for paths: one pass closes every joint of a chain, where a pass of one joint at a
// time leaves most of the error spread along it.
TEST(joint_paths, one_pass_closes_a_chain_that_one_joint_at_a_time_does_not) {
    // Each joint a millimetre open: the solve is exact for the chain's linearised motion, and
    // leaves only the second order of the links' turning.
    const vector3 gap{scalar(0.0004), scalar(-0.001), scalar(0.0003)};
    auto world = make_chain(40, gap);
    world.build();
    auto before = world.worst_separation();
    project_joint_paths(world.paths, world.bodies, 1, 60, true, nullptr);
    auto after = world.worst_separation();
    EXPECT_LT(after, before * scalar(0.005)) << "from " << before << " m to " << after << " m";

    auto one_at_a_time = make_chain(40, gap);
    for (auto *anchor : one_at_a_time.pivots) {
        update_point_mass(*anchor, one_at_a_time.bodies[anchor->body[0]],
                          one_at_a_time.bodies[anchor->body[1]],
                          current_pose(*anchor, one_at_a_time.bodies[anchor->body[0]],
                                       one_at_a_time.bodies[anchor->body[1]]));
    }
    for (auto *anchor : one_at_a_time.pivots)
        project_point(*anchor, one_at_a_time.bodies[anchor->body[0]], one_at_a_time.bodies[anchor->body[1]],
                      1, 60);
    EXPECT_GT(one_at_a_time.worst_separation(), before * scalar(0.3))
        << "one joint at a time left " << one_at_a_time.worst_separation() << " m";
}

TEST(joint_paths, one_pass_closes_a_chain_whose_joints_point_either_way) {
    // Every other joint listed from its lower body, so that each shared body is on the same
    // side of one neighbouring joint and on different sides of the next, along 21 turned rods.
    const vector3 gap{scalar(-0.0006), scalar(0.001), scalar(0.0002)};
    joint_world world(22);
    world.join(0, 1, vector3_zero, behind, gap);
    for (solver_body_index i = 1; i < 21; ++i) {
        if (i % 2 == 0)
            world.join(i, i + 1, ahead, behind, gap);
        else
            world.join(i + 1, i, behind, ahead, -gap);
    }
    turn_rods(world);
    world.build();
    ASSERT_EQ(world.num_paths(), 1u);
    auto before = world.worst_separation();
    project_joint_paths(world.paths, world.bodies, 1, 60, true, nullptr);
    auto after = world.worst_separation();
    EXPECT_LT(after, before * scalar(0.005)) << "from " << before << " m to " << after << " m";
}

TEST(joint_paths, a_pass_moves_the_bodies_only_as_the_joints_pull_them) {
    // Linear and angular momentum: the corrections are equal and opposite position impulses
    // between free bodies, so their mass-weighted motion sums to zero.
    joint_world world(4);
    world.join(1, 2, ahead, behind, {scalar(0.001), 0, scalar(0.002)});
    world.join(2, 3, ahead, behind, {0, scalar(-0.002), 0});
    world.build();
    project_joint_paths(world.paths, world.bodies, 1, 60, true, nullptr);
    vector3 moved = vector3_zero;
    for (solver_body_index i = 1; i < 4; ++i)
        moved += world.bodies[i].delta_position;
    EXPECT_LT(length(moved), scalar(1e-7)) << "the centre of mass moved by " << length(moved) << " m";
    EXPECT_LT(world.worst_separation(), scalar(2e-5)) << "a free path of two joints is closed in one pass";
}

TEST(joint_paths, a_later_pass_leaves_gaps_of_a_few_micrometres_to_the_next_sub_step) {
    // A Y: three arms of two rods meet at body 1, so that no path is isolated.
    joint_world world(8);
    const vector3 gap{0, scalar(2e-5), 0};
    for (solver_body_index arm = 0; arm < 3; ++arm) {
        auto first = 2 + 2 * arm;
        world.join(1, first, ahead, behind, gap);
        world.join(first, first + 1, ahead, behind, gap);
    }
    world.build();
    project_joint_paths(world.paths, world.bodies, 1, 60, true, nullptr);
    // Each arm's solve moves body 1, which opens the arms solved before it by a few micrometres.
    auto after_first = world.worst_separation();
    ASSERT_GT(after_first, scalar(1e-6));
    ASSERT_LT(after_first, scalar(1e-5));

    // A later pass leaves such gaps to the next sub-step: no body moves.
    std::vector<vector3> before;
    for (auto &body : world.bodies)
        before.push_back(body.delta_position);
    project_joint_paths(world.paths, world.bodies, 1, 60, false, nullptr);
    for (std::size_t i = 0; i < world.bodies.size(); ++i)
        EXPECT_EQ(world.bodies[i].delta_position, before[i]) << "body " << i;

    // The tip of an arm moved by 50 µm: the pass closes its arm, with the first pass's factors.
    world.bodies[3].delta_position += vector3{0, scalar(5e-5), 0};
    project_joint_paths(world.paths, world.bodies, 1, 60, false, nullptr);
    EXPECT_LT(world.worst_separation(), scalar(1e-5));
}

// The factors measure each joint's own K at the poses after the integration; the next warm start
// takes its inverse from them once instead of measuring it again.
TEST(joint_paths, a_factored_pass_hands_each_joint_its_mass_for_the_next_warm_start) {
    // Long enough for the blocks to be measured in several groups of joints, one of them partly
    // filled, and the rods turned so that every entry of their inertia counts.
    auto world = make_chain(19, {0, scalar(-0.002), 0});
    turn_rods(world);
    world.build();
    // The factors measure K before the pass moves the bodies.
    std::vector<matrix3x3> before;
    for (auto *anchor : world.pivots) {
        auto &a = world.bodies[anchor->body[0]];
        auto &b = world.bodies[anchor->body[1]];
        ASSERT_TRUE(inverse_point_mass(a, b, current_pose(*anchor, a, b), before.emplace_back()));
        EXPECT_FALSE(anchor->point_mass_current);
    }
    project_joint_paths(world.paths, world.bodies, 1, 60, true, nullptr);
    for (std::size_t k = 0; k < world.pivots.size(); ++k) {
        auto *anchor = world.pivots[k];
        auto &a = world.bodies[anchor->body[0]];
        auto &b = world.bodies[anchor->body[1]];
        ASSERT_TRUE(anchor->point_mass_current);
        ASSERT_TRUE(anchor->point_mass_valid);
        // The factors measure the blocks several joints at a time, each exactly as
        // inverse_point_mass() measures one.
        auto &expected = before[k];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_EQ(anchor->point_mass[i][j], expected[i][j]);

        // Kept once, even for a pose far from the one measured...
        auto far = current_pose(*anchor, a, b);
        far.rA = far.rA * scalar(3);
        far.rB = far.rB * scalar(3);
        warm_point_mass(*anchor, a, b, far);
        EXPECT_FALSE(anchor->point_mass_current);
        EXPECT_NEAR(anchor->point_mass[0][0], expected[0][0], std::abs(expected[0][0]) * 1e-5);
        // ...then kept while neither arm has moved by more than max_point_mass_turn of its length
        // since the step began...
        auto near = current_pose(*anchor, a, b);
        near.rA = anchor->rA * (1 + max_point_mass_turn / 2);
        near.rB = anchor->rB * (1 + max_point_mass_turn / 2);
        warm_point_mass(*anchor, a, b, near);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_EQ(anchor->point_mass[i][j], expected[i][j]);
        // ...and measured at the pose given once one has.
        warm_point_mass(*anchor, a, b, far);
        matrix3x3 at_far;
        ASSERT_EQ(inverse_point_mass(a, b, far, at_far), anchor->point_mass_valid);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_EQ(anchor->point_mass[i][j], at_far[i][j]);
    }
}

TEST(joint_paths, passes_give_the_same_bits_on_any_thread_count) {
    // Many chains and Y shapes with random gaps, joints listed in a random order.
    auto make = [] {
        joint_world world(1 + 60 * 7);
        std::mt19937 rng(5);
        std::uniform_real_distribution<scalar> gap(scalar(-0.001), scalar(0.001));
        auto random_gap = [&] { return vector3{gap(rng), gap(rng), gap(rng)}; };
        std::vector<std::array<solver_body_index, 2>> joints;
        for (solver_body_index group = 0; group < 60; ++group) {
            auto first = 1 + 7 * group;
            if (group % 2 == 0) {
                joints.push_back({0, first});
                for (solver_body_index i = 0; i < 6; ++i)
                    joints.push_back({first + i, first + i + 1});
            } else {
                for (solver_body_index arm = 0; arm < 3; ++arm) {
                    joints.push_back({first, first + 1 + 2 * arm});
                    joints.push_back({first + 1 + 2 * arm, first + 2 + 2 * arm});
                }
            }
        }
        std::shuffle(joints.begin(), joints.end(), rng);
        for (auto [a, b] : joints)
            world.join(a, b, a == 0 ? vector3_zero : ahead, behind, random_gap());
        world.build();
        return world;
    };
    auto run = [](joint_world &world, task_scheduler *scheduler) {
        for (int pass = 0; pass < 4; ++pass)
            project_joint_paths(world.paths, world.bodies, 1, 60, pass == 0, scheduler);
    };
    auto in_order = make();
    auto before = in_order.worst_separation();
    run(in_order, nullptr);
    // The chains close in the first pass; the three arms of each Y meet at a free body, which
    // the passes settle, halving their error each.
    ASSERT_LT(in_order.worst_separation(), before * scalar(0.2)) << "from " << before << " m";
    for (unsigned threads : {1u, 2u, 4u}) {
        task_scheduler scheduler(threads);
        auto world = make();
        run(world, &scheduler);
        for (std::size_t i = 0; i < world.bodies.size(); ++i) {
            auto &a = in_order.bodies[i], &b = world.bodies[i];
            EXPECT_EQ(std::memcmp(&a.delta_position, &b.delta_position, sizeof(vector3)), 0)
                << "body " << i << ", " << threads << " threads";
            EXPECT_EQ(std::memcmp(&a.delta_rotation, &b.delta_rotation, sizeof(quaternion)), 0)
                << "body " << i << ", " << threads << " threads";
        }
    }
}
