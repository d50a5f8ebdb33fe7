// The testbed application: a window, the running sample's registry, the camera and the mouse
// and keyboard, and the frame loop that steps the physics and draws. The same object renders
// the off-screen screenshots.
#ifndef EDYN_TESTBED_APP_HPP
#define EDYN_TESTBED_APP_HPP

#include "camera.hpp"
#include "debug_draw.hpp"
#include "picking.hpp"
#include "renderer.hpp"
#include "samples.hpp"
#include "script.hpp"
#include "world.hpp"
#include <deque>
#include <edyn/edyn.hpp>
#include <memory>
#include <string>

struct GLFWwindow;

namespace testbed {

// Where the time went, in milliseconds, over the last frame and the last seconds.
struct frame_stats {
    double physics_ms{0};           // inside edyn::update (or the single step)
    double draw_ms{0};              // building the draw lists, drawing and waiting for the GPU
    double draw_lists_ms{0};        // of which building the instance lists on the CPU
    double frame_ms{0};             // the whole frame, swap included
    unsigned steps{0};              // fixed steps run in the last frame
    double ms_per_step{0};          // physics_ms / steps, of the last frame that stepped
    std::deque<float> step_history; // ms per step, one value per frame that stepped
    int draw_calls{0};
    std::size_t bodies{0}, manifolds{0}, contact_points{0}, islands{0}, sleeping_islands{0};
    // Pages of paged meshes loaded now, of all (loaded is unknown in asynchronous mode).
    std::size_t pages{0}, loaded_pages{0};
};

// The mouse as a frame sees it: read from GLFW in a window, or played from a script.
struct pointer_state {
    float x{0}, y{0}; // pixels, origin top left
    bool left{false}, right{false}, middle{false}, shift{false};
    float wheel{0};       // clicks this frame
    bool captured{false}; // over the panel
};

struct controls {
    bool paused{false};
    bool slow_motion{false};
    float slow_factor{0.25f};
    bool step_once{false};
    bool reset{false};
    bool show_ray{false};
    bool show_panel{true};
    debug_options debug;
};

class app {
public:
    app(GLFWwindow *window, bool with_ui);
    ~app();
    app(const app &) = delete;
    app &operator=(const app &) = delete;

    void load(const sample &s);
    // The interactive loop, until the window closes or, when max_frames is not 0, for that many
    // frames; then prints where the time went on average.
    void run(unsigned max_frames = 0);
    // Runs `steps` fixed steps, then the script's frames (one fixed step each, the pointer
    // played from the script, what it did printed as "script: ..." lines), draws one frame and
    // writes it to `path`.
    bool screenshot(unsigned steps, const std::vector<script_command> &script, const std::string &path);

    // For the panel.
    const sample *current_sample() const { return current; }
    const sample_state &current_state() const { return state; }
    world_settings settings;
    frame_stats stats;
    controls ctl;
    ray_probe probe; // the cursor ray and its hit, when shown
    orbit_camera camera;
    const sample *requested{nullptr}; // set by the panel to switch samples
    void apply_settings();

    void on_key(int key, int action, int mods);

private:
    GLFWwindow *window;
    bool with_ui;
    std::unique_ptr<renderer> gfx;
    std::unique_ptr<edyn::registry> registry;
    const sample *current{nullptr};
    sample_state state;
    body_dragger dragger;
    double sim_clock{0};
    pointer_state last_pointer;

    pointer_state read_pointer() const;
    void handle_pointer(const pointer_state &p, int width, int height);
    // One frame of a script: the pointer, one fixed step, its results applied.
    void script_frame(const pointer_state &p, int width, int height);
    void play_script(const std::vector<script_command> &script, int width, int height);
    void step_physics(double frame_dt);
    void draw_frame(int width, int height, bool ui);
    void gather_stats();
    sample_input keyboard_input() const;
};

} // namespace testbed

#endif // EDYN_TESTBED_APP_HPP
