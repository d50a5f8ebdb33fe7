#ifndef EDYN_CONFIG_VERSION_HPP
#define EDYN_CONFIG_VERSION_HPP

#include <string_view>

namespace edyn {

/// Version of the edyn library, as semantic versioning numbers.
struct version_info {
    int major, minor, patch;

    /// @var major
    /// Major version: raised by changes that break the API.
    /// @var minor
    /// Minor version: raised by additions that keep the API compatible.
    /// @var patch
    /// Patch version: raised by fixes only.
};

/// Version of the compiled library, which may differ from the headers an application was built
/// with when it links an older installed copy.
/// @return The major, minor and patch numbers the library was built with.
version_info version() noexcept;

/// Version of the compiled library as text, for example `"0.1.0"`.
/// @return A view of a string with static storage duration.
std::string_view version_string() noexcept;

/// Whether the library was compiled with `edyn::scalar` = `double` (CMake option
/// `EDYN_DOUBLE_PRECISION`). An application must be built with the same choice as the library it
/// links, or the layout of every math type differs.
/// @return True for a double-precision build, false for the default single precision.
bool built_with_double_precision() noexcept;

} // namespace edyn

#endif // EDYN_CONFIG_VERSION_HPP
