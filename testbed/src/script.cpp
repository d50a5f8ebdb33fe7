#include "script.hpp"
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace testbed {

namespace {

struct command_syntax {
    const char *word;
    script_action action;
    bool has_point;
    bool has_frames;
};

constexpr command_syntax syntax[] = {
    {"press", script_action::press, true, false},      {"move", script_action::move, true, true},
    {"release", script_action::release, false, false}, {"wait", script_action::wait, false, true},
    {"ray", script_action::ray, true, false},          {"shoot", script_action::shoot, true, false},
};

[[noreturn]] void bad(const std::string &command, const std::string &why) {
    throw std::invalid_argument("script command '" + command + "': " + why +
                                " (commands: press X Y; move X Y FRAMES; release; wait FRAMES; ray X Y; "
                                "shoot X Y)");
}

std::string trim(const std::string &s) {
    auto first = s.find_first_not_of(" \t\n");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\n") - first + 1);
}

} // namespace

std::vector<script_command> parse_script(const std::string &text, int width, int height) {
    std::vector<script_command> commands;
    std::istringstream all(text);
    std::string part;
    while (std::getline(all, part, ';')) {
        auto command = trim(part);
        if (command.empty()) continue;
        std::istringstream words(command);
        std::string word;
        words >> word;
        const command_syntax *found = nullptr;
        for (auto &s : syntax)
            if (word == s.word) found = &s;
        if (!found) bad(command, "unknown command '" + word + "'");
        script_command c{found->action};
        if (found->has_point) {
            if (!(words >> c.x >> c.y)) bad(command, "needs a pixel X Y");
            if (!(std::isfinite(c.x) && std::isfinite(c.y) && c.x >= 0 && c.y >= 0 && c.x < float(width) &&
                  c.y < float(height)))
                bad(command, "the pixel must lie in the " + std::to_string(width) + " x " +
                                 std::to_string(height) + " image");
        }
        if (found->has_frames) {
            long frames = 0;
            if (!(words >> frames)) bad(command, "needs a number of frames");
            if (frames < 1 || frames > 10000) bad(command, "frames must be 1 to 10000");
            c.frames = unsigned(frames);
        }
        std::string extra;
        if (words >> extra) bad(command, "unexpected '" + extra + "'");
        commands.push_back(c);
    }
    return commands;
}

} // namespace testbed
