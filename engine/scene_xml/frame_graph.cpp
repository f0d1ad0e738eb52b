#include "scene_xml/frame_graph.h"

#include "scene_xml/message_text.h"

#include <algorithm>
#include <map>
#include <string>

namespace mhd::scene_xml {

void check_frame_graph(const std::vector<FrameDescription>& frames, Diagnostics& out) {
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::map<std::string, std::size_t, std::less<>> index_of;
  for (std::size_t i = 0; i < frames.size(); ++i) index_of.emplace(frames[i].name, i);

  // parent[i]: index of frame i's parent, kNone for "world" or an unknown parent.
  std::vector<std::size_t> parent(frames.size(), kNone);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const FrameDescription& f = frames[i];
    if (index_of.at(f.name) != i || f.parent == "world") continue;  // duplicates reported elsewhere
    const auto it = index_of.find(f.parent);
    if (it == index_of.end()) {
      out.push_back({f.where, concat("frame '", f.name, "' has unknown parent '", f.parent, "'")});
    } else {
      parent[i] = it->second;
    }
  }

  enum class State { Unvisited, OnPath, Done };
  std::vector<State> state(frames.size(), State::Unvisited);
  std::vector<std::size_t> path;
  for (std::size_t start = 0; start < frames.size(); ++start) {
    path.clear();
    std::size_t i = start;
    while (i != kNone && state[i] == State::Unvisited) {
      state[i] = State::OnPath;
      path.push_back(i);
      i = parent[i];
    }
    if (i != kNone && state[i] == State::OnPath) {
      // path from i to the end is the cycle; name it from its member defined first.
      std::vector<std::size_t> cycle(std::find(path.begin(), path.end(), i), path.end());
      std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
      std::string chain;
      for (const std::size_t c : cycle) chain += concat(frames[c].name, " -> ");
      chain += frames[cycle.front()].name;
      out.push_back({frames[cycle.front()].where, concat("frame parent cycle: ", chain)});
    }
    for (const std::size_t p : path) state[p] = State::Done;
  }
}

}  // namespace mhd::scene_xml
