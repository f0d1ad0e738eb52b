// `mhd try --script`'s timed input (engine/viewer/input_script.h): every event kind, and
// each kind of mistake named at its line.

#include "viewer/input_script.h"

#include <gtest/gtest.h>

namespace mhd::viewer {
namespace {

TEST(InputScript, ReadsEveryEventKindWithCommentsAndBlankLines) {
  const Result<std::vector<ScriptedEvent>> r = parse_input_script(
      "# push in\n"
      "\n"
      "2 press 240 160\n"
      "3 drag 240.5 140   # down 20 px\n"
      "3 release 240.5 140\n"
      "5 scroll -4\n"
      "6 key w\n"
      "7 key PageUp\n"
      "8 key PageDown\n"
      "9 key Home\n",
      "s.txt");
  ASSERT_TRUE(r.ok()) << r.error_text();
  ASSERT_EQ(r->size(), 8u);
  EXPECT_EQ(r.value()[0].frame, 2);
  EXPECT_EQ(r.value()[0].event.kind, InputEvent::Kind::Press);
  EXPECT_EQ(r.value()[0].event.button, 1);
  EXPECT_EQ(r.value()[1].event.kind, InputEvent::Kind::Drag);
  EXPECT_DOUBLE_EQ(r.value()[1].event.x_px, 240.5);
  EXPECT_DOUBLE_EQ(r.value()[1].event.y_px, 140.0);
  EXPECT_EQ(r.value()[2].event.kind, InputEvent::Kind::Release);
  EXPECT_EQ(r.value()[3].event.kind, InputEvent::Kind::Scroll);
  EXPECT_EQ(r.value()[3].event.scroll_steps, -4);
  EXPECT_EQ(r.value()[4].event.key, 'w');
  EXPECT_EQ(r.value()[5].event.key, kKeyPageUp);
  EXPECT_EQ(r.value()[6].event.key, kKeyPageDown);
  EXPECT_EQ(r.value()[7].event.key, kKeyHome);
}

TEST(InputScript, NamesTheLineOfEachMistake) {
  EXPECT_EQ(parse_input_script("1 key w\nx press 1 2\n", "s.txt").error_text(),
            "s.txt:2: error: 'x' is not a frame number (0 or more)");
  EXPECT_EQ(parse_input_script("-1 key w\n", "s.txt").error_text(), "s.txt:1: error: '-1' is not a frame number (0 or more)");
  EXPECT_EQ(parse_input_script("5 key w\n4 key s\n", "s.txt").error_text(),
            "s.txt:2: error: frame 4 comes before the previous event's frame 5");
  EXPECT_EQ(parse_input_script("1 click 3 4\n", "s.txt").error_text(),
            "s.txt:1: error: unknown event 'click' (press, drag, release, scroll or key)");
  EXPECT_EQ(parse_input_script("1 drag 3\n", "s.txt").error_text(), "s.txt:1: error: 'drag' needs the pointer's X Y in pixels");
  EXPECT_EQ(parse_input_script("1 scroll 0\n", "s.txt").error_text(),
            "s.txt:1: error: 'scroll' needs a non-zero whole number of notches");
  EXPECT_EQ(parse_input_script("1 key Escape\n", "s.txt").error_text(),
            "s.txt:1: error: unknown key 'Escape' (a character, PageUp, PageDown or Home)");
  EXPECT_EQ(parse_input_script("1 key w w\n", "s.txt").error_text(), "s.txt:1: error: unexpected 'w' after the event");
  const Result<std::vector<ScriptedEvent>> r = parse_input_script("1 key w\n2 key\n", "s.txt");
  EXPECT_EQ(r.error_text(), "s.txt:2: error: 'key' needs a key");
  EXPECT_FALSE(r.ok());  // no events from a script with a mistake
}

TEST(InputScript, AMissingFileIsAnError) {
  EXPECT_EQ(read_input_script("/nonexistent/script.txt").error_text(),
            "/nonexistent/script.txt: error: cannot read the input script");
}

}  // namespace
}  // namespace mhd::viewer
