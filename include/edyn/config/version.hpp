#ifndef EDYN_CONFIG_VERSION_HPP
#define EDYN_CONFIG_VERSION_HPP

#include <string_view>

namespace edyn {

struct version_info {
    int major, minor, patch;
};

// Version of the compiled library, which may differ from the headers an application was
// built with when it links an older installed copy.
version_info version() noexcept;
std::string_view version_string() noexcept;

// Whether the library was compiled with edyn::scalar = double.
bool built_with_double_precision() noexcept;

} // namespace edyn

#endif // EDYN_CONFIG_VERSION_HPP
