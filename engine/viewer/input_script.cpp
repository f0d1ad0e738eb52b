#include "viewer/input_script.h"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace mhd::viewer {
namespace {

std::string parse_key(const std::string& word, int& key) {
  if (word == "PageUp") key = kKeyPageUp;
  else if (word == "PageDown") key = kKeyPageDown;
  else if (word == "Home") key = kKeyHome;
  else if (word.size() == 1 && word[0] > ' ' && word[0] < 127) key = word[0];
  else return fmt::format("unknown key '{}' (a character, PageUp, PageDown or Home)", word);
  return {};
}

/// One line's event after its frame number, or why it is not one.
std::string parse_event(std::istringstream& in, InputEvent& e) {
  std::string kind;
  in >> kind;
  if (kind == "press" || kind == "drag" || kind == "release") {
    e.kind = kind == "press" ? InputEvent::Kind::Press
             : kind == "drag" ? InputEvent::Kind::Drag
                              : InputEvent::Kind::Release;
    if (!(in >> e.x_px >> e.y_px) || !std::isfinite(e.x_px) || !std::isfinite(e.y_px)) {
      return fmt::format("'{}' needs the pointer's X Y in pixels", kind);
    }
  } else if (kind == "scroll") {
    e.kind = InputEvent::Kind::Scroll;
    if (!(in >> e.scroll_steps) || e.scroll_steps == 0) return "'scroll' needs a non-zero whole number of notches";
  } else if (kind == "key") {
    e.kind = InputEvent::Kind::Key;
    std::string word;
    if (!(in >> word)) return "'key' needs a key";
    if (std::string why = parse_key(word, e.key); !why.empty()) return why;
  } else {
    return fmt::format("unknown event '{}' (press, drag, release, scroll or key)", kind);
  }
  std::string extra;
  if (in >> extra) return fmt::format("unexpected '{}' after the event", extra);
  return {};
}

}  // namespace

Result<std::vector<ScriptedEvent>> parse_input_script(const std::string& text, const std::string& file_name) {
  std::vector<ScriptedEvent> events;
  std::istringstream lines(text);
  std::string line;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream in(line);
    std::string first;
    if (!(in >> first)) continue;
    ScriptedEvent s;
    std::size_t used = 0;
    std::string why;
    try {
      s.frame = std::stoi(first, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != first.size() || s.frame < 0) why = fmt::format("'{}' is not a frame number (0 or more)", first);
    else if (!events.empty() && s.frame < events.back().frame) {
      why = fmt::format("frame {} comes before the previous event's frame {}", s.frame, events.back().frame);
    } else {
      why = parse_event(in, s.event);
    }
    if (!why.empty()) return Diagnostic{SourceLocation{file_name, line_number}, why};
    events.push_back(s);
  }
  return events;
}

Result<std::vector<ScriptedEvent>> read_input_script(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return Diagnostic{SourceLocation{file.string(), 0}, "cannot read the input script"};
  std::ostringstream text;
  text << in.rdbuf();
  return parse_input_script(text.str(), file.string());
}

}  // namespace mhd::viewer
