#ifndef EDYN_SHAPES_PAGED_TRIANGLE_MESH_HPP
#define EDYN_SHAPES_PAGED_TRIANGLE_MESH_HPP

#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/static_tree.hpp"
#include "edyn/shapes/triangle_mesh.hpp"
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace edyn {

// The triangles of one page of a paged_triangle_mesh, in the mesh's space.
struct triangle_mesh_page {
    std::vector<vector3> vertices;
    std::vector<std::uint32_t> indices;
    // Empty, or one per vertex.
    std::vector<scalar> friction;
    std::vector<scalar> restitution;
    // Each triangle's active edges (bit i: edge i), as the whole mesh has them.
    std::vector<std::uint8_t> edge_flags;
};

// Where the pages of a paged_triangle_mesh come from. load() is called on the mesh's loading
// thread, one page at a time, and may block (on a file, a network); it returns an initialized
// triangle_mesh, or null when the page cannot be had (the page then stays empty: nothing
// collides with it, and it is asked for again the next time a body needs it).
class triangle_mesh_page_loader {
public:
    virtual ~triangle_mesh_page_loader() = default;
    virtual std::shared_ptr<triangle_mesh> load(std::size_t page) = 0;
};

// Keeps every page's arrays in memory and builds a page's triangle_mesh (normals, tree) only
// while it is loaded.
std::unique_ptr<triangle_mesh_page_loader> make_memory_page_loader(std::vector<triangle_mesh_page> pages);

// Writes every page to its own file in `directory` (which must exist), named
// page_<index>.edynpage, and reads a page from its file when it is loaded. Throws
// std::runtime_error when a file cannot be written.
std::unique_ptr<triangle_mesh_page_loader> make_file_page_loader(const std::vector<triangle_mesh_page> &pages,
                                                                 const std::string &directory);

// A triangle mesh too large to keep in memory whole (a large terrain), split into pages of
// at most a given number of triangles under a tree of their bounds. The simulation loads the
// pages that bodies near (their bounds grown by the distance they travel in `lookahead_time`)
// on a background thread, and unloads those no body has neared for `unload_delay` steps. A
// body over a page whose load has not finished waits for it: the step completes the load
// before the body's collision, so no body falls through a page that was late.
//
// Triangles are numbered across pages: page p holds triangles first_triangle(p) onwards.
// Collision features carry that number in `part`. A paged mesh belongs to one world (its
// loading state is the world's); its triangles behave as triangle_mesh's, edges between pages
// included.
class paged_triangle_mesh {
public:
    // Seconds of travel ahead of a body whose pages are loaded in advance.
    scalar lookahead_time{scalar(0.5)};
    // Steps a page stays loaded once no body needs it.
    std::uint32_t unload_delay{60};

    // Pages with the given bounds and triangle counts, from `loader`. Prefer
    // create_paged_triangle_mesh. Throws std::invalid_argument for no pages, mismatched counts
    // or a null loader.
    paged_triangle_mesh(std::vector<AABB> page_aabbs, std::vector<std::size_t> page_triangles,
                        std::unique_ptr<triangle_mesh_page_loader> loader);
    ~paged_triangle_mesh();
    paged_triangle_mesh(const paged_triangle_mesh &) = delete;
    paged_triangle_mesh &operator=(const paged_triangle_mesh &) = delete;

    std::size_t num_pages() const noexcept { return pages.size(); }
    std::size_t num_triangles() const noexcept { return first_triangles.back(); }
    std::size_t first_triangle(std::size_t page) const noexcept { return first_triangles[page]; }
    // The page holding triangle `triangle` (numbered across pages).
    std::size_t page_of_triangle(std::size_t triangle) const noexcept;
    const AABB &get_aabb() const noexcept { return tree.root_aabb(); }
    const AABB &get_page_aabb(std::size_t page) const noexcept { return pages[page].aabb; }

    bool is_page_loaded(std::size_t page) const noexcept { return pages[page].mesh != nullptr; }
    // The page's mesh while it is loaded, else null.
    const triangle_mesh *get_page(std::size_t page) const noexcept { return pages[page].mesh.get(); }
    std::size_t num_loaded_pages() const noexcept;
    std::size_t num_loaded_triangles() const noexcept;

    // Calls func(page_index, const triangle_mesh &) for every loaded page whose bounds
    // overlap `aabb` (mesh space), in a fixed order.
    template<typename Func>
    void visit_loaded_pages(const AABB &aabb, Func &&func) const {
        tree.visit([&](const AABB &node) { return intersect(node, aabb); },
                   [&](std::size_t p) {
                       if (pages[p].mesh) func(p, *pages[p].mesh);
                   });
    }

    // The simulation's side, called by the step on the thread that steps the world.

    // Starts loading, in the background, the pages that overlap `region` (mesh space), and
    // marks them in use at `step`.
    void request(const AABB &region, std::uint64_t step);
    // Loads now the pages that overlap `region` and are not loaded, waiting for those being
    // loaded; marks them in use at `step`.
    void require(const AABB &region, std::uint64_t step);
    // Takes the pages whose background load finished.
    void collect();
    // Unloads the pages not in use since `step - unload_delay`.
    void unload_unused(std::uint64_t step);

private:
    enum class page_state : std::uint8_t { unloaded, queued, loaded };
    struct page {
        AABB aabb;
        std::shared_ptr<triangle_mesh> mesh;
        page_state state{page_state::unloaded};
        std::uint64_t last_used{0};
    };

    void enqueue(std::size_t page, bool urgent);
    void loader_loop();

    std::vector<page> pages;
    std::vector<std::size_t> first_triangles; // One more than pages: the total last.
    static_tree tree;
    std::unique_ptr<triangle_mesh_page_loader> loader;

    // Shared with the loading thread.
    std::mutex mutex;
    std::condition_variable cv;
    std::deque<std::size_t> queue;
    std::vector<std::pair<std::size_t, std::shared_ptr<triangle_mesh>>> done;
    bool stopping{false};
    std::thread thread; // Started with the first load.
};

// Splits a mesh into pages of at most `max_triangles_per_page` triangles, by median splits of
// the triangles' centres along the widest axis, and makes a paged mesh of them. Edges keep the
// activity they have in the whole mesh. With `colors` (one per vertex, as
// load_tri_mesh_from_obj gives them), red becomes each vertex's friction and green its
// restitution. With a `directory`, pages are written there and read back when loaded
// (make_file_page_loader); otherwise they stay in memory (make_memory_page_loader). Throws
// std::invalid_argument for a page size of 0, colours of the wrong count, or a mesh that
// triangle_mesh::initialize() refuses (the message names it).
std::shared_ptr<paged_triangle_mesh> create_paged_triangle_mesh(const std::vector<vector3> &vertices,
                                                                const std::vector<std::uint32_t> &indices,
                                                                std::size_t max_triangles_per_page,
                                                                const std::vector<vector3> *colors = nullptr,
                                                                const std::string &directory = {});

} // namespace edyn

#endif // EDYN_SHAPES_PAGED_TRIANGLE_MESH_HPP
