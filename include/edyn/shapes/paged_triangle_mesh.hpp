#ifndef EDYN_SHAPES_PAGED_TRIANGLE_MESH_HPP
#define EDYN_SHAPES_PAGED_TRIANGLE_MESH_HPP

#include "edyn/parallel/background_tasks.hpp"
#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/static_tree.hpp"
#include "edyn/shapes/triangle_mesh.hpp"
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace edyn {

/// The triangles of one page of a paged_triangle_mesh, in the mesh's space: the arrays a page
/// loader keeps or stores for a page.
struct triangle_mesh_page {
    std::vector<vector3> vertices;      ///< Vertex positions (m).
    std::vector<std::uint32_t> indices; ///< Three indices into `vertices` per triangle.
    /// Per-vertex friction coefficients: empty, or one per vertex.
    std::vector<scalar> friction;
    /// Per-vertex restitution coefficients in [0, 1]: empty, or one per vertex.
    std::vector<scalar> restitution;
    /// Each triangle's active edges (bit i: edge i), as the whole mesh has them.
    std::vector<std::uint8_t> edge_flags;
};

/// Where the pages of a paged_triangle_mesh come from; derive from it to load pages from your
/// own storage.
///
/// load() is called by the world's background tasks (see background_tasks: a program's own
/// scheduler, when init_config::scheduler gives one), or on the thread that steps the world when
/// a body needs a page at once; one page at a time, and it may block (on a file, a network).
/// make_memory_page_loader() and make_file_page_loader() give ready-made loaders.
class triangle_mesh_page_loader {
public:
    virtual ~triangle_mesh_page_loader() = default;
    /// Loads one page; called on any thread, never concurrently with itself, and never after
    /// the paged_triangle_mesh that owns the loader is destroyed.
    /// @param page Index of the page.
    /// @return An initialized triangle_mesh holding the page's triangles, in the same order and
    ///         count as given to paged_triangle_mesh, or null when the page cannot be had (an
    ///         exception counts as null). The page then stays empty: nothing collides with it,
    ///         and it is asked for again the next time a body needs it.
    virtual std::shared_ptr<triangle_mesh> load(std::size_t page) = 0;
    /// The pages, when the loader keeps them all in memory (make_memory_page_loader()), so that
    /// the mesh can be sent to a peer whole; null by default, for pages that come from elsewhere.
    /// @return The pages, indexed by page number, or null.
    virtual const std::vector<triangle_mesh_page> *memory_pages() const noexcept { return nullptr; }
    /// The directory of page files the loader reads (make_file_page_loader(),
    /// open_file_page_loader()), so that a peer can read the same files; empty by default.
    /// @return The directory, or an empty string.
    virtual std::string page_directory() const { return {}; }
};

/// Makes a page loader that keeps every page's arrays in memory and builds a page's
/// triangle_mesh (normals, tree) only while it is loaded.
/// @param pages The pages, indexed by page number.
/// @return The loader, to give to paged_triangle_mesh.
std::unique_ptr<triangle_mesh_page_loader> make_memory_page_loader(std::vector<triangle_mesh_page> pages);

/// Makes a page loader that writes every page to its own file in `directory` now, named
/// page_<index>.edynpage, and reads a page from its file when it is loaded.
/// @param pages The pages, indexed by page number.
/// @param directory An existing directory.
/// @return The loader, to give to paged_triangle_mesh.
/// @throws std::runtime_error When a file cannot be written.
std::unique_ptr<triangle_mesh_page_loader> make_file_page_loader(const std::vector<triangle_mesh_page> &pages,
                                                                 const std::string &directory);

/// Makes a page loader that reads the page files make_file_page_loader() wrote in `directory`
/// (in this run or another), writing nothing. A page whose file is missing or malformed fails to
/// load (it stays empty).
/// @param directory The directory of the page files.
/// @return The loader, to give to paged_triangle_mesh.
std::unique_ptr<triangle_mesh_page_loader> open_file_page_loader(const std::string &directory);

/// A triangle mesh too large to keep in memory whole (a large terrain), split into pages of
/// at most a given number of triangles under a tree of their bounds.
///
/// The simulation loads the pages that bodies near (their bounds grown by the distance they
/// travel in `lookahead_time`) in the background, as tasks of the world's background_tasks (so
/// through the program's scheduler when init_config::scheduler gives one), and unloads those no
/// body has neared for `unload_delay` steps. A body over a page whose load has not finished waits
/// for it: the step completes the load before the body's collision, loading the page itself when
/// no task has started on it yet, so no body falls through a page that was late. A page is
/// never loaded by two tasks at once.
///
/// Triangles are numbered across pages: page p holds triangles first_triangle(p) onwards.
/// Collision features carry that number in `part`. A paged mesh belongs to one world (its
/// loading state is the world's); its triangles behave as triangle_mesh's, edges between pages
/// included. Make one with create_paged_triangle_mesh() and give it to a body as a
/// paged_mesh_shape.
class paged_triangle_mesh {
public:
    /// Seconds of travel ahead of a body whose pages are loaded in advance (s); 0.5 by default.
    scalar lookahead_time{scalar(0.5)};
    /// Steps a page stays loaded once no body needs it; 60 by default.
    std::uint32_t unload_delay{60};

    /// Pages with the given bounds and triangle counts, from `loader`. Prefer
    /// create_paged_triangle_mesh(), which computes all three.
    /// @param page_aabbs Bounds of each page in the mesh's space (m).
    /// @param page_triangles Number of triangles of each page.
    /// @param loader Where the pages come from.
    /// @throws std::invalid_argument For no pages, mismatched counts or a null loader.
    paged_triangle_mesh(std::vector<AABB> page_aabbs, std::vector<std::size_t> page_triangles,
                        std::unique_ptr<triangle_mesh_page_loader> loader);
    /// Cancels the loads not started yet and waits for the one in progress, if any: the loader
    /// is not called once this returns. Background tasks still queued for it do nothing then.
    ~paged_triangle_mesh();
    paged_triangle_mesh(const paged_triangle_mesh &) = delete;
    paged_triangle_mesh &operator=(const paged_triangle_mesh &) = delete;

    /// Number of pages.
    std::size_t num_pages() const noexcept { return pages.size(); }
    /// Number of triangles of all pages together.
    std::size_t num_triangles() const noexcept { return first_triangles.back(); }
    /// Number, across pages, of the page's first triangle.
    /// @param page Index of the page (not checked).
    std::size_t first_triangle(std::size_t page) const noexcept { return first_triangles[page]; }
    /// Number of triangles of a page, loaded or not.
    /// @param page Index of the page (not checked).
    std::size_t num_page_triangles(std::size_t page) const noexcept {
        return first_triangles[page + 1] - first_triangles[page];
    }
    /// Where the pages come from (read only: to send the mesh to a peer).
    const triangle_mesh_page_loader &get_loader() const noexcept;
    /// The page holding triangle `triangle` (numbered across pages).
    std::size_t page_of_triangle(std::size_t triangle) const noexcept;
    /// Bounds of all pages, in the mesh's space.
    const AABB &get_aabb() const noexcept { return tree.root_aabb(); }
    /// Bounds of one page, in the mesh's space.
    /// @param page Index of the page (not checked).
    const AABB &get_page_aabb(std::size_t page) const noexcept { return pages[page].aabb; }

    /// Whether the page's mesh is in memory. Read on the thread that steps the world.
    /// @param page Index of the page (not checked).
    bool is_page_loaded(std::size_t page) const noexcept { return pages[page].mesh != nullptr; }
    /// The page's mesh while it is loaded, else null.
    /// @param page Index of the page (not checked).
    const triangle_mesh *get_page(std::size_t page) const noexcept { return pages[page].mesh.get(); }
    /// Number of pages whose mesh is in memory.
    std::size_t num_loaded_pages() const noexcept;
    /// Number of triangles in the pages whose mesh is in memory.
    std::size_t num_loaded_triangles() const noexcept;

    /// Calls `func(page_index, const triangle_mesh &)` for every loaded page whose bounds
    /// overlap `aabb`, in a fixed order.
    /// @param aabb The query box in the mesh's space (m).
    /// @param func Callable taking a `std::size_t` page index and the page's mesh.
    template<typename Func>
    void visit_loaded_pages(const AABB &aabb, Func &&func) const {
        tree.visit([&](const AABB &node) { return intersect(node, aabb); },
                   [&](std::size_t p) {
                       if (pages[p].mesh) func(p, *pages[p].mesh);
                   });
    }

    /// Starts loading, as tasks posted to `tasks`, the pages that overlap `region` and are not
    /// loaded or being loaded, and marks them in use at `step`.
    ///
    /// This and the three functions below are the simulation's side, called by the step on the
    /// thread that steps the world (one thread at a time).
    /// @param region The region in the mesh's space (m).
    /// @param step Number of the current step.
    /// @param tasks Where the loads run: the world's background tasks.
    void request(const AABB &region, std::uint64_t step, background_tasks &tasks);
    /// Loads now, on the calling thread, the pages that overlap `region` and are neither loaded
    /// nor being loaded, and waits for those a task is loading; marks them in use at `step`. A
    /// page whose load fails stays empty for this step.
    /// @param region The region in the mesh's space (m).
    /// @param step Number of the current step.
    void require(const AABB &region, std::uint64_t step);
    /// Takes in the pages whose load finished, making them visible to queries.
    void collect();
    /// Unloads the pages not in use since `step - unload_delay`.
    /// @param step Number of the current step.
    void unload_unused(std::uint64_t step);

private:
    enum class page_state : std::uint8_t { unloaded, queued, loaded };
    struct loading;
    struct load_ticket;
    struct page {
        AABB aabb;
        std::shared_ptr<triangle_mesh> mesh;
        page_state state{page_state::unloaded};
        std::uint64_t last_used{0};
        // While queued: claimed by the one who loads the page (a task, or require()).
        std::shared_ptr<load_ticket> ticket;
    };

    std::vector<page> pages;
    std::vector<std::size_t> first_triangles; // One more than pages: the total last.
    static_tree tree;
    // The loader and the finished loads, shared with the tasks (which may outlive the mesh).
    std::shared_ptr<loading> shared;
};

/// Splits a mesh into pages and makes a paged mesh of them, ready for a paged_mesh_shape.
///
/// Pages hold at most `max_triangles_per_page` triangles, found by median splits of the
/// triangles' centres along the widest axis. Edges keep the activity they have in the whole
/// mesh. With a `directory`, pages are written there and read back when loaded
/// (make_file_page_loader()); otherwise they stay in memory (make_memory_page_loader()).
/// @param vertices Vertex positions in the mesh's space (m).
/// @param indices Three indices into `vertices` per triangle, counter-clockwise seen from the
///        front.
/// @param max_triangles_per_page Most triangles of a page; positive.
/// @param colors Optional, one per vertex (as load_tri_mesh_from_obj() gives them): red becomes
///        each vertex's friction (finite, not negative) and green its restitution (in [0, 1]).
/// @param directory Optional existing directory to keep the pages in, as files.
/// @return The paged mesh, shared.
/// @throws std::invalid_argument For a page size of 0, colours of the wrong count or out of
///         range (the message names the vertex), or a mesh that
///         triangle_mesh::initialize() refuses (the message names it).
/// @throws std::runtime_error When a page file cannot be written.
std::shared_ptr<paged_triangle_mesh> create_paged_triangle_mesh(const std::vector<vector3> &vertices,
                                                                const std::vector<std::uint32_t> &indices,
                                                                std::size_t max_triangles_per_page,
                                                                const std::vector<vector3> *colors = nullptr,
                                                                const std::string &directory = {});

} // namespace edyn

#endif // EDYN_SHAPES_PAGED_TRIANGLE_MESH_HPP
