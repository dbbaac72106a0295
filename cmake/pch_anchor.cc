// The translation unit of the precompiled-header owner targets (cmake/precompiled_headers.cmake):
// CMake builds a target's precompiled header alongside its sources, so the owner needs one.
namespace mocapfill::pch_anchor {
int Anchor() { return 0; }
}  // namespace mocapfill::pch_anchor
