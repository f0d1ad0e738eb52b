#pragma once
// Checks the rig's frame tree once every file is read: each parent is "world" or a
// frame, and following parents from any frame reaches "world" (no cycles).

#include "diagnostics/diagnostic.h"
#include "scene/scene_description.h"

#include <vector>

namespace mhd::scene_xml {

/// Appends "frame 'a' has unknown parent 'b'" and "frame parent cycle: a -> b -> a"
/// diagnostics (a cycle once, at its member defined first, listed child to parent).
/// Frames with a duplicate name are judged by their first definition.
void check_frame_graph(const std::vector<FrameDescription>& frames, Diagnostics& out);

}  // namespace mhd::scene_xml
