#include "edyn/shapes/paged_triangle_mesh.hpp"
#include "invalid_argument.hpp"
#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <fstream>
#include <mutex>
#include <numeric>
#include <span>
#include <stdexcept>
#include <unordered_map>

namespace edyn {

using detail::throw_invalid_argument;

namespace {

std::shared_ptr<triangle_mesh> build_page(const triangle_mesh_page &page) {
    auto mesh = std::make_shared<triangle_mesh>();
    mesh->insert_vertices(page.vertices.begin(), page.vertices.end());
    mesh->insert_indices(page.indices.begin(), page.indices.end());
    mesh->insert_friction_coefficients(page.friction.begin(), page.friction.end());
    mesh->insert_restitution_coefficients(page.restitution.begin(), page.restitution.end());
    mesh->initialize(page.edge_flags);
    return mesh;
}

class memory_page_loader final : public triangle_mesh_page_loader {
public:
    explicit memory_page_loader(std::vector<triangle_mesh_page> pages)
        : pages(std::move(pages)) {}

    std::shared_ptr<triangle_mesh> load(std::size_t page) override {
        if (page >= pages.size()) return nullptr;
        try {
            return build_page(pages[page]);
        } catch (const std::exception &) {
            return nullptr;
        }
    }

    const std::vector<triangle_mesh_page> *memory_pages() const noexcept override { return &pages; }

private:
    std::vector<triangle_mesh_page> pages;
};

// Page files: a tag, the five array lengths, then the arrays as stored in memory.
constexpr char page_file_tag[8] = {'E', 'D', 'Y', 'N', 'P', 'G', '0', char(sizeof(scalar))};

std::string page_path(const std::string &directory, std::size_t page) {
    return directory + "/page_" + std::to_string(page) + ".edynpage";
}

template<typename T>
void write_array(std::ofstream &out, const std::vector<T> &values) {
    out.write(reinterpret_cast<const char *>(values.data()), std::streamsize(values.size() * sizeof(T)));
}

template<typename T>
bool read_array(std::ifstream &in, std::vector<T> &values, std::uint64_t count, std::uint64_t &bytes_left) {
    if (count > bytes_left / sizeof(T)) return false;
    values.resize(count);
    in.read(reinterpret_cast<char *>(values.data()), std::streamsize(count * sizeof(T)));
    bytes_left -= count * sizeof(T);
    return bool(in);
}

class file_page_loader final : public triangle_mesh_page_loader {
public:
    explicit file_page_loader(std::string directory)
        : directory(std::move(directory)) {}

    std::shared_ptr<triangle_mesh> load(std::size_t index) override {
        std::ifstream in(page_path(directory, index), std::ios::binary | std::ios::ate);
        if (!in) return nullptr;
        auto size = std::uint64_t(in.tellg());
        in.seekg(0);
        char tag[sizeof(page_file_tag)];
        std::uint64_t counts[5];
        in.read(tag, sizeof(tag));
        in.read(reinterpret_cast<char *>(counts), sizeof(counts));
        if (!in || std::memcmp(tag, page_file_tag, sizeof(tag)) != 0) return nullptr;
        auto left = size - sizeof(tag) - sizeof(counts);
        triangle_mesh_page page;
        if (!read_array(in, page.vertices, counts[0], left) ||
            !read_array(in, page.indices, counts[1], left) ||
            !read_array(in, page.friction, counts[2], left) ||
            !read_array(in, page.restitution, counts[3], left) ||
            !read_array(in, page.edge_flags, counts[4], left)) {
            return nullptr;
        }
        try {
            return build_page(page);
        } catch (const std::exception &) {
            return nullptr;
        }
    }

    std::string page_directory() const override { return directory; }

private:
    std::string directory;
};

} // namespace

std::unique_ptr<triangle_mesh_page_loader> make_memory_page_loader(std::vector<triangle_mesh_page> pages) {
    return std::make_unique<memory_page_loader>(std::move(pages));
}

std::unique_ptr<triangle_mesh_page_loader> make_file_page_loader(const std::vector<triangle_mesh_page> &pages,
                                                                 const std::string &directory) {
    for (std::size_t p = 0; p < pages.size(); ++p) {
        const auto &page = pages[p];
        std::ofstream out(page_path(directory, p), std::ios::binary | std::ios::trunc);
        std::uint64_t counts[5] = {page.vertices.size(), page.indices.size(), page.friction.size(),
                                   page.restitution.size(), page.edge_flags.size()};
        out.write(page_file_tag, sizeof(page_file_tag));
        out.write(reinterpret_cast<const char *>(counts), sizeof(counts));
        write_array(out, page.vertices);
        write_array(out, page.indices);
        write_array(out, page.friction);
        write_array(out, page.restitution);
        write_array(out, page.edge_flags);
        if (!out) throw std::runtime_error("make_file_page_loader: cannot write " + page_path(directory, p));
    }
    return std::make_unique<file_page_loader>(directory);
}

// What the mesh shares with its load tasks, which may run on any thread and may still be queued
// when the mesh is destroyed.
struct paged_triangle_mesh::loading {
    std::unique_ptr<triangle_mesh_page_loader> loader;
    // Loaders need not be thread-safe: one load at a time.
    std::mutex load_mutex;
    // Guards what follows and the tickets' `claimed`.
    std::mutex mutex;
    std::condition_variable cv;
    std::vector<std::pair<std::size_t, std::shared_ptr<triangle_mesh>>> done;
    unsigned running{0}; // Loads claimed and not yet in `done`.

    // Claims the ticket: true for the one caller that is to load the page.
    bool claim(load_ticket &ticket);
    // Loads a page whose ticket the caller claimed and hands it over through `done`.
    void load(std::size_t index);
};

struct paged_triangle_mesh::load_ticket {
    bool claimed{false}; // Under loading::mutex.
};

bool paged_triangle_mesh::loading::claim(load_ticket &ticket) {
    std::lock_guard lock(mutex);
    if (ticket.claimed) return false;
    ticket.claimed = true;
    ++running;
    return true;
}

void paged_triangle_mesh::loading::load(std::size_t index) {
    std::shared_ptr<triangle_mesh> mesh;
    {
        std::lock_guard lock(load_mutex);
        try {
            mesh = loader->load(index);
        } catch (...) {
            mesh = nullptr;
        }
    }
    {
        std::lock_guard lock(mutex);
        done.emplace_back(index, std::move(mesh));
        --running;
    }
    cv.notify_all();
}

std::unique_ptr<triangle_mesh_page_loader> open_file_page_loader(const std::string &directory) {
    return std::make_unique<file_page_loader>(directory);
}

paged_triangle_mesh::paged_triangle_mesh(std::vector<AABB> page_aabbs,
                                         std::vector<std::size_t> page_triangles,
                                         std::unique_ptr<triangle_mesh_page_loader> loader)
    : shared(std::make_shared<loading>()) {
    if (page_aabbs.empty()) throw_invalid_argument("paged_triangle_mesh: there must be at least one page");
    if (page_triangles.size() != page_aabbs.size()) {
        throw_invalid_argument("paged_triangle_mesh: ", page_aabbs.size(), " page bounds but ",
                               page_triangles.size(), " triangle counts");
    }
    if (!loader) throw_invalid_argument("paged_triangle_mesh: loader is null");
    shared->loader = std::move(loader);
    pages.resize(page_aabbs.size());
    first_triangles.assign(1, 0);
    for (std::size_t p = 0; p < pages.size(); ++p) {
        pages[p].aabb = page_aabbs[p];
        first_triangles.push_back(first_triangles.back() + page_triangles[p]);
    }
    tree.build(page_aabbs);
}

paged_triangle_mesh::~paged_triangle_mesh() {
    // Tasks not started find their ticket claimed and do nothing; the load in progress, if any,
    // finishes before the loader (owned by `shared`) may be destroyed with the mesh's owner.
    std::unique_lock lock(shared->mutex);
    for (auto &p : pages) {
        if (p.ticket) p.ticket->claimed = true;
    }
    shared->cv.wait(lock, [&] { return shared->running == 0; });
}

const triangle_mesh_page_loader &paged_triangle_mesh::get_loader() const noexcept { return *shared->loader; }

std::size_t paged_triangle_mesh::page_of_triangle(std::size_t triangle) const noexcept {
    auto it = std::upper_bound(first_triangles.begin(), first_triangles.end(), triangle);
    return std::size_t(it - first_triangles.begin()) - 1;
}

std::size_t paged_triangle_mesh::num_loaded_pages() const noexcept {
    return std::size_t(
        std::count_if(pages.begin(), pages.end(), [](const page &p) { return p.mesh != nullptr; }));
}

std::size_t paged_triangle_mesh::num_loaded_triangles() const noexcept {
    std::size_t count = 0;
    for (const auto &p : pages) {
        if (p.mesh) count += p.mesh->num_triangles();
    }
    return count;
}

void paged_triangle_mesh::collect() {
    std::vector<std::pair<std::size_t, std::shared_ptr<triangle_mesh>>> finished;
    {
        std::lock_guard lock(shared->mutex);
        if (shared->done.empty()) return;
        finished.swap(shared->done);
    }
    for (auto &[index, mesh] : finished) {
        auto &p = pages[index];
        // A failed load leaves the page unloaded: it is asked for again when needed.
        p.mesh = std::move(mesh);
        p.state = p.mesh ? page_state::loaded : page_state::unloaded;
        p.ticket.reset();
    }
}

void paged_triangle_mesh::request(const AABB &region, std::uint64_t step, background_tasks &tasks) {
    tree.visit([&](const AABB &node) { return intersect(node, region); },
               [&](std::size_t index) {
                   auto &p = pages[index];
                   p.last_used = step;
                   if (p.state != page_state::unloaded) return;
                   p.state = page_state::queued;
                   p.ticket = std::make_shared<load_ticket>();
                   // The task holds the shared state, not the mesh: it may run after the mesh is
                   // gone, and then finds its ticket claimed.
                   tasks.post([shared = shared, ticket = p.ticket, index] {
                       if (shared->claim(*ticket)) shared->load(index);
                   });
               });
}

void paged_triangle_mesh::require(const AABB &region, std::uint64_t step) {
    std::vector<std::size_t> waiting;
    tree.visit([&](const AABB &node) { return intersect(node, region); },
               [&](std::size_t index) {
                   auto &p = pages[index];
                   p.last_used = step;
                   if (p.state == page_state::loaded) return;
                   if (p.state == page_state::unloaded) {
                       p.state = page_state::queued;
                       p.ticket = std::make_shared<load_ticket>();
                   }
                   waiting.push_back(index);
               });
    for (auto index : waiting) {
        // Loaded here unless a task has started on it (or finished it): never twice at once.
        if (auto ticket = pages[index].ticket; ticket && shared->claim(*ticket)) shared->load(index);
        // Each page is waited for once: a failed load leaves it unloaded for this step.
        for (;;) {
            collect();
            if (pages[index].state != page_state::queued) break;
            std::unique_lock lock(shared->mutex);
            shared->cv.wait(lock, [&] { return !shared->done.empty(); });
        }
    }
}

void paged_triangle_mesh::unload_unused(std::uint64_t step) {
    for (auto &p : pages) {
        if (p.state == page_state::loaded && p.last_used + unload_delay < step) {
            p.mesh.reset();
            p.state = page_state::unloaded;
        }
    }
}

namespace {

// Orders `tris` (triangle indices) so that consecutive runs of at most `max` triangles are
// compact: median splits of the centres along the widest axis. Appends each run's size.
void split_pages(std::span<std::uint32_t> tris, const std::vector<vector3> &centres, std::size_t max_size,
                 std::vector<std::size_t> &sizes) {
    if (tris.size() <= max_size) {
        sizes.push_back(tris.size());
        return;
    }
    AABB bounds{vector3_max, -vector3_max};
    for (auto t : tris)
        bounds = {min(bounds.min, centres[t]), max(bounds.max, centres[t])};
    auto axis = max_index(bounds.max - bounds.min);
    auto mid = tris.size() / 2;
    std::nth_element(tris.begin(), tris.begin() + mid, tris.end(), [&](std::uint32_t a, std::uint32_t b) {
        return centres[a][axis] < centres[b][axis] || (centres[a][axis] == centres[b][axis] && a < b);
    });
    split_pages(tris.first(mid), centres, max_size, sizes);
    split_pages(tris.subspan(mid), centres, max_size, sizes);
}

} // namespace

std::shared_ptr<paged_triangle_mesh> create_paged_triangle_mesh(const std::vector<vector3> &vertices,
                                                                const std::vector<std::uint32_t> &indices,
                                                                std::size_t max_triangles_per_page,
                                                                const std::vector<vector3> *colors,
                                                                const std::string &directory) {
    const char *fn = "create_paged_triangle_mesh";
    if (max_triangles_per_page == 0) throw_invalid_argument(fn, ": max_triangles_per_page must be positive");
    if (colors && colors->size() != vertices.size()) {
        throw_invalid_argument(fn, ": there must be one colour per vertex (", vertices.size(), "), got ",
                               colors->size());
    }
    // The whole mesh, for its validation and its edges' activity across pages.
    triangle_mesh whole;
    std::vector<scalar> friction, restitution;
    try {
        whole.insert_vertices(vertices.begin(), vertices.end());
        whole.insert_indices(indices.begin(), indices.end());
        if (colors) {
            // Checked here, where the caller can hear of it: a page's load would refuse them,
            // and leave the page empty under the bodies over it.
            for (std::size_t i = 0; i < colors->size(); ++i) {
                const auto &c = (*colors)[i];
                if (!(std::isfinite(c.x) && c.x >= 0))
                    throw_invalid_argument(fn, ": colour ", i,
                                           ": red (friction) must be finite and not negative, got ", c.x);
                if (!(c.y >= 0 && c.y <= 1))
                    throw_invalid_argument(fn, ": colour ", i,
                                           ": green (restitution) must be in [0, 1], got ", c.y);
                friction.push_back(c.x);
                restitution.push_back(c.y);
            }
        }
        whole.initialize();
    } catch (const std::invalid_argument &e) {
        throw_invalid_argument(fn, ": ", e.what());
    }

    auto num_tri = whole.num_triangles();
    std::vector<vector3> centres(num_tri);
    for (std::size_t t = 0; t < num_tri; ++t) {
        auto tri = whole.get_triangle_vertices(t);
        centres[t] = (tri[0] + tri[1] + tri[2]) / scalar(3);
    }
    std::vector<std::uint32_t> order(num_tri);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::size_t> sizes;
    split_pages(order, centres, max_triangles_per_page, sizes);

    std::vector<triangle_mesh_page> pages;
    std::vector<AABB> aabbs;
    auto flags = whole.get_edge_flags();
    std::size_t offset = 0;
    for (auto size : sizes) {
        triangle_mesh_page page;
        std::unordered_map<std::uint32_t, std::uint32_t> renumbered;
        AABB aabb{vector3_max, -vector3_max};
        for (std::size_t k = offset; k < offset + size; ++k) {
            auto t = order[k];
            for (std::size_t i = 0; i < 3; ++i) {
                auto v = whole.get_vertex_index(t, i);
                auto [it, inserted] = renumbered.try_emplace(v, std::uint32_t(page.vertices.size()));
                if (inserted) {
                    page.vertices.push_back(vertices[v]);
                    if (colors) {
                        page.friction.push_back(friction[v]);
                        page.restitution.push_back(restitution[v]);
                    }
                    aabb = {min(aabb.min, vertices[v]), max(aabb.max, vertices[v])};
                }
                page.indices.push_back(it->second);
            }
            page.edge_flags.push_back(flags[t]);
        }
        offset += size;
        pages.push_back(std::move(page));
        aabbs.push_back(aabb);
    }
    auto loader =
        directory.empty() ? make_memory_page_loader(pages) : make_file_page_loader(pages, directory);
    return std::make_shared<paged_triangle_mesh>(std::move(aabbs), std::move(sizes), std::move(loader));
}

} // namespace edyn
