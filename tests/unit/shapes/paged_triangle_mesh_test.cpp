// Paged triangle meshes: how create_paged_triangle_mesh splits a mesh, loading in the
// background and on demand, unloading, file-backed pages, and bad input.
#include <atomic>
#include <chrono>
#include <edyn/edyn.hpp>
#include <edyn_scenes/scenes.hpp>
#include <filesystem>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <thread>

using namespace edyn;

namespace {

struct grid_data {
    std::vector<vector3> vertices;
    std::vector<std::uint32_t> indices;
};

// A cells x cells grid of 1 m squares (two triangles each) with gentle hills.
grid_data make_grid(unsigned cells) {
    auto mesh =
        scenes::make_grid_mesh(cells, 1, [](scalar x, scalar z) { return scenes::terrain_height(x, z, 2); });
    auto v = mesh->get_vertices();
    auto i = mesh->get_indices();
    return {{v.begin(), v.end()}, {i.begin(), i.end()}};
}

// Polls collect() until `page` is loaded or a second has passed.
bool wait_loaded(paged_triangle_mesh &paged, std::size_t page) {
    for (int i = 0; i < 1000 && !paged.is_page_loaded(page); ++i) {
        paged.collect();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return paged.is_page_loaded(page);
}

// A thin column through p, above and below the terrain.
AABB point_box(const vector3 &p) { return {p - vector3{0.1, 10, 0.1}, p + vector3{0.1, 10, 0.1}}; }

} // namespace

TEST(paged_triangle_mesh_test, pages_hold_every_triangle_once_and_at_most_the_page_size) {
    auto grid = make_grid(40); // 3,200 triangles.
    auto paged = create_paged_triangle_mesh(grid.vertices, grid.indices, 100);
    ASSERT_GE(paged->num_pages(), 32u);
    EXPECT_EQ(paged->num_triangles(), 3200u);
    EXPECT_EQ(paged->first_triangle(0), 0u);
    // Load everything and check each page against its bounds and size.
    paged->require(paged->get_aabb(), 0);
    EXPECT_EQ(paged->num_loaded_pages(), paged->num_pages());
    EXPECT_EQ(paged->num_loaded_triangles(), 3200u);
    for (std::size_t p = 0; p < paged->num_pages(); ++p) {
        const auto *page = paged->get_page(p);
        ASSERT_NE(page, nullptr);
        EXPECT_LE(page->num_triangles(), 100u);
        EXPECT_EQ(paged->first_triangle(p) + page->num_triangles(),
                  p + 1 < paged->num_pages() ? paged->first_triangle(p + 1) : paged->num_triangles());
        EXPECT_TRUE(contains(paged->get_page_aabb(p), page->get_aabb())) << "page " << p;
        EXPECT_EQ(paged->page_of_triangle(paged->first_triangle(p)), p);
        EXPECT_EQ(paged->page_of_triangle(paged->first_triangle(p) + page->num_triangles() - 1), p);
    }
}

TEST(paged_triangle_mesh_test, edges_between_pages_keep_the_whole_mesh_activity) {
    // A flat grid: no edge is active but those on its outer border.
    auto mesh = scenes::make_grid_mesh(20, 1, [](scalar, scalar) { return scalar(0); });
    auto v = mesh->get_vertices();
    auto i = mesh->get_indices();
    auto paged = create_paged_triangle_mesh({v.begin(), v.end()}, {i.begin(), i.end()}, 50);
    paged->require(paged->get_aabb(), 0);
    std::size_t active = 0;
    for (std::size_t p = 0; p < paged->num_pages(); ++p) {
        const auto *page = paged->get_page(p);
        for (std::size_t t = 0; t < page->num_triangles(); ++t) {
            for (std::size_t e = 0; e < 3; ++e)
                active += page->is_edge_active(t, e);
        }
    }
    // 20 boundary edges per side of the square.
    EXPECT_EQ(active, 80u);
}

TEST(paged_triangle_mesh_test, pages_load_in_the_background_on_request_and_at_once_on_require) {
    auto grid = make_grid(40);
    auto paged = create_paged_triangle_mesh(grid.vertices, grid.indices, 100);
    EXPECT_EQ(paged->num_loaded_pages(), 0u);

    // require: the pages under the region are there on return.
    auto corner = vector3{-19.5, 0, -19.5};
    paged->require(point_box(corner), 1);
    std::size_t corner_page = paged->num_pages();
    for (std::size_t p = 0; p < paged->num_pages(); ++p) {
        if (intersect(paged->get_page_aabb(p), point_box(corner))) {
            EXPECT_TRUE(paged->is_page_loaded(p)) << "page " << p;
            corner_page = p;
        }
    }
    ASSERT_LT(corner_page, paged->num_pages());
    auto loaded = paged->num_loaded_pages();
    EXPECT_LT(loaded, paged->num_pages() / 4);

    // request: loaded by a background task, taken by collect().
    background_tasks tasks;
    auto other = vector3{19.5, 0, 19.5};
    paged->request(point_box(other), 1, tasks);
    std::size_t other_page = paged->num_pages();
    for (std::size_t p = 0; p < paged->num_pages(); ++p) {
        if (intersect(paged->get_page_aabb(p), point_box(other))) other_page = p;
    }
    ASSERT_LT(other_page, paged->num_pages());
    EXPECT_TRUE(wait_loaded(*paged, other_page));

    // Unused for longer than unload_delay steps: unloaded; used recently: kept.
    paged->unload_delay = 10;
    paged->require(point_box(other), 20);
    paged->unload_unused(20);
    EXPECT_FALSE(paged->is_page_loaded(corner_page));
    EXPECT_TRUE(paged->is_page_loaded(other_page));
    paged->unload_unused(31);
    EXPECT_EQ(paged->num_loaded_pages(), 0u);
    EXPECT_EQ(paged->num_loaded_triangles(), 0u);
}

TEST(paged_triangle_mesh_test, colours_become_per_vertex_friction_and_restitution) {
    auto grid = make_grid(10);
    std::vector<vector3> colors;
    for (const auto &v : grid.vertices)
        colors.push_back({(v.x + 5) / 10, scalar(0.25), 0});
    auto paged = create_paged_triangle_mesh(grid.vertices, grid.indices, 50, &colors);
    paged->require(paged->get_aabb(), 0);
    for (std::size_t p = 0; p < paged->num_pages(); ++p) {
        const auto *page = paged->get_page(p);
        ASSERT_TRUE(page->has_per_vertex_friction());
        ASSERT_TRUE(page->has_per_vertex_restitution());
        for (std::size_t t = 0; t < page->num_triangles(); ++t) {
            auto x = page->get_vertex(page->get_vertex_index(t, 0)).x;
            EXPECT_NEAR(page->get_friction(t, {1, 0, 0}), (x + 5) / 10, 1e-5);
            EXPECT_NEAR(page->get_restitution(t, {1, 0, 0}), 0.25, 1e-6);
        }
    }
}

TEST(paged_triangle_mesh_test, file_backed_pages_load_from_their_files) {
    auto dir = std::filesystem::temp_directory_path() /
               ("edyn_pages_" + std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())));
    std::filesystem::create_directories(dir);
    auto grid = make_grid(20);
    auto paged = create_paged_triangle_mesh(grid.vertices, grid.indices, 100, nullptr, dir.string());
    ASSERT_TRUE(std::filesystem::exists(dir / "page_0.edynpage"));
    paged->require(paged->get_aabb(), 0);
    EXPECT_EQ(paged->num_loaded_triangles(), 800u);

    // A page whose file went missing stays unloaded; the rest load.
    paged->unload_delay = 0;
    paged->unload_unused(10);
    std::filesystem::remove(dir / "page_0.edynpage");
    paged->require(paged->get_aabb(), 20);
    EXPECT_FALSE(paged->is_page_loaded(0));
    EXPECT_EQ(paged->num_loaded_pages(), paged->num_pages() - 1);
    // Corrupt: truncated.
    paged->unload_unused(30);
    std::filesystem::resize_file(dir / "page_1.edynpage", 20);
    paged->require(paged->get_aabb(), 40);
    EXPECT_FALSE(paged->is_page_loaded(1));
    std::filesystem::remove_all(dir);
}

TEST(paged_triangle_mesh_test, bad_input_throws_naming_the_function) {
    auto grid = make_grid(4);
    auto expect_message = [](auto &&fn, const std::string &part) {
        try {
            fn();
            FAIL() << "no exception, expected one naming " << part;
        } catch (const std::invalid_argument &e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    expect_message([&] { create_paged_triangle_mesh(grid.vertices, grid.indices, 0); },
                   "max_triangles_per_page");
    std::vector<vector3> colors(3);
    expect_message([&] { create_paged_triangle_mesh(grid.vertices, grid.indices, 10, &colors); }, "colour");
    // A colour out of range would leave the page holding it empty when it loads, under the bodies
    // over it: refused here, naming the vertex.
    colors.assign(grid.vertices.size(), vector3{scalar(0.5), scalar(0.5), 0});
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    for (auto c : {vector3{nan, 0, 0}, vector3{0, nan, 0}, vector3{-1, 0, 0}, vector3{0, scalar(1.5), 0},
                   vector3{std::numeric_limits<scalar>::infinity(), 0, 0}, vector3{0, -1, 0}}) {
        auto bad_colors = colors;
        bad_colors[7] = c;
        expect_message([&] { create_paged_triangle_mesh(grid.vertices, grid.indices, 10, &bad_colors); },
                       "colour 7");
    }
    colors[7] = {5, 1, 0}; // Friction above 1 is a friction.
    EXPECT_NO_THROW(create_paged_triangle_mesh(grid.vertices, grid.indices, 10, &colors));
    auto bad = grid.indices;
    bad[4] = 1000;
    expect_message([&] { create_paged_triangle_mesh(grid.vertices, bad, 10); }, "create_paged_triangle_mesh");
    expect_message([&] { create_paged_triangle_mesh(grid.vertices, {}, 10); }, "no indices");
    expect_message([&] { paged_triangle_mesh({}, {}, make_memory_page_loader({})); }, "at least one page");
    expect_message([&] { paged_triangle_mesh({AABB{}}, {1}, nullptr); }, "loader is null");
}

namespace {

// Loads pages from memory, counting the loads of each page, the most at once, and holding each
// load until `open` is set.
struct gated_loader final : triangle_mesh_page_loader {
    std::unique_ptr<triangle_mesh_page_loader> pages;
    std::shared_ptr<std::atomic<bool>> open = std::make_shared<std::atomic<bool>>(true);
    std::shared_ptr<std::vector<std::atomic<int>>> loads;
    std::shared_ptr<std::atomic<int>> started = std::make_shared<std::atomic<int>>(0);
    std::shared_ptr<std::atomic<int>> running = std::make_shared<std::atomic<int>>(0);
    std::shared_ptr<std::atomic<int>> most_running = std::make_shared<std::atomic<int>>(0);

    gated_loader(const std::vector<triangle_mesh_page> &source)
        : pages(make_memory_page_loader(source))
        , loads(std::make_shared<std::vector<std::atomic<int>>>(source.size())) {}

    std::shared_ptr<triangle_mesh> load(std::size_t page) override {
        ++(*loads)[page];
        ++*started;
        auto now = ++*running;
        for (auto most = most_running->load();
             now > most && !most_running->compare_exchange_weak(most, now);) {
        }
        while (!open->load())
            std::this_thread::yield();
        auto mesh = pages->load(page);
        --*running;
        return mesh;
    }
};

// The same pages as `source`, from a gated_loader whose counters `loader` shares.
std::shared_ptr<paged_triangle_mesh> gated_copy(const paged_triangle_mesh &source, gated_loader *&loader) {
    std::vector<AABB> aabbs;
    std::vector<std::size_t> counts;
    for (std::size_t p = 0; p < source.num_pages(); ++p) {
        aabbs.push_back(source.get_page_aabb(p));
        counts.push_back(source.num_page_triangles(p));
    }
    auto owned = std::make_unique<gated_loader>(*source.get_loader().memory_pages());
    loader = owned.get();
    return std::make_shared<paged_triangle_mesh>(aabbs, counts, std::move(owned));
}

} // namespace

TEST(paged_triangle_mesh_test, a_page_a_task_is_loading_is_waited_for_not_loaded_again) {
    auto grid = make_grid(20);
    auto source = create_paged_triangle_mesh(grid.vertices, grid.indices, 100);
    gated_loader *loader = nullptr;
    auto paged = gated_copy(*source, loader);
    auto open = loader->open;
    auto loads = loader->loads;
    auto started = loader->started;
    auto most_running = loader->most_running;
    *open = false;
    background_tasks tasks;
    auto where = vector3{-9.5, 0, -9.5};
    paged->request(point_box(where), 1, tasks);
    while (started->load() == 0)
        std::this_thread::yield();
    // The task is inside load(): require() must wait for it, not load the page a second time.
    std::thread release([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        *open = true;
    });
    paged->require(point_box(where), 1);
    release.join();
    std::size_t under = 0;
    for (std::size_t p = 0; p < paged->num_pages(); ++p) {
        if (!intersect(paged->get_page_aabb(p), point_box(where))) continue;
        ++under;
        EXPECT_TRUE(paged->is_page_loaded(p)) << "page " << p;
        EXPECT_EQ((*loads)[p].load(), 1) << "page " << p << " loaded more than once";
    }
    EXPECT_GE(under, 1u);
    EXPECT_EQ(most_running->load(), 1) << "the loader ran concurrently with itself";
}

TEST(paged_triangle_mesh_test, the_mesh_can_be_destroyed_while_a_load_is_in_flight) {
    auto grid = make_grid(20);
    auto source = create_paged_triangle_mesh(grid.vertices, grid.indices, 100);
    ASSERT_GE(source->num_pages(), 4u);
    gated_loader *loader = nullptr;
    auto paged = gated_copy(*source, loader);
    auto open = loader->open;
    auto started = loader->started;
    *open = false;
    std::atomic<bool> destroyed{false};
    {
        background_tasks tasks;                      // Declared after `paged` goes: outlives the mesh.
        paged->request(paged->get_aabb(), 1, tasks); // Every page: one loading, the rest queued.
        while (started->load() == 0)
            std::this_thread::yield();
        std::thread destroyer([&] {
            paged.reset();
            destroyed = true;
        });
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        EXPECT_FALSE(destroyed.load()) << "the destructor did not wait for the load in progress";
        *open = true;
        destroyer.join();
        EXPECT_TRUE(destroyed.load());
    } // The tasks still queued run now, and must not call the loader of the mesh that is gone.
    EXPECT_EQ(started->load(), 1);
}
