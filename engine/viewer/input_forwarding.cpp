#include "viewer/input_forwarding.h"

#include <optional>

namespace mhd::viewer {
namespace {

/// The pointer in window pixels, y up, whatever range and orientation the event carries.
void pointer_px(const osgGA::GUIEventAdapter& e, InputEvent& out) {
  const double width = e.getWindowWidth() > 0 ? static_cast<double>(e.getWindowWidth())
                                              : static_cast<double>(e.getXmax() - e.getXmin());
  const double height = e.getWindowHeight() > 0 ? static_cast<double>(e.getWindowHeight())
                                                : static_cast<double>(e.getYmax() - e.getYmin());
  out.x_px = 0.5 * (static_cast<double>(e.getXnormalized()) + 1.0) * width;
  out.y_px = 0.5 * (static_cast<double>(e.getYnormalized()) + 1.0) * height;
}

int button_number(int osg_mask) {
  switch (osg_mask) {
    case osgGA::GUIEventAdapter::MIDDLE_MOUSE_BUTTON: return 2;
    case osgGA::GUIEventAdapter::RIGHT_MOUSE_BUTTON: return 3;
    default: return 1;
  }
}

std::optional<InputEvent> from_osg(const osgGA::GUIEventAdapter& e) {
  using E = osgGA::GUIEventAdapter;
  InputEvent out;
  switch (e.getEventType()) {
    case E::PUSH:
      out.kind = InputEvent::Kind::Press;
      out.button = button_number(e.getButton());
      break;
    case E::DRAG:
      out.kind = InputEvent::Kind::Drag;
      break;
    case E::RELEASE:
      out.kind = InputEvent::Kind::Release;
      out.button = button_number(e.getButton());
      break;
    case E::SCROLL:
      out.kind = InputEvent::Kind::Scroll;
      if (e.getScrollingMotion() == E::SCROLL_UP) out.scroll_steps = 1;
      else if (e.getScrollingMotion() == E::SCROLL_DOWN) out.scroll_steps = -1;
      else return std::nullopt;
      return out;
    case E::KEYDOWN:
      out.kind = InputEvent::Kind::Key;
      out.key = e.getKey();
      return out;
    default:
      return std::nullopt;
  }
  pointer_px(e, out);
  return out;
}

}  // namespace

bool InputForwarder::handle(const osgGA::GUIEventAdapter& event, osgGA::GUIActionAdapter& /*action*/) {
  const std::optional<InputEvent> e = from_osg(event);
  if (!e) return false;
  handler_(*e);
  return true;
}

// EventQueue numbers buttons 1 left, 2 middle, 3 right, as InputEvent does.
void push_input_event(osgGA::EventQueue& queue, const InputEvent& event, int width_px, int height_px) {
  // Window-like pixel coordinates, y up, so from_osg reads back what was pushed.
  queue.getCurrentEventState()->setWindowRectangle(0, 0, width_px, height_px);
  queue.setMouseInputRange(0.0f, 0.0f, static_cast<float>(width_px), static_cast<float>(height_px));
  queue.getCurrentEventState()->setMouseYOrientation(osgGA::GUIEventAdapter::Y_INCREASING_UPWARDS);
  const auto x = static_cast<float>(event.x_px);
  const auto y = static_cast<float>(event.y_px);
  switch (event.kind) {
    case InputEvent::Kind::Press: queue.mouseButtonPress(x, y, static_cast<unsigned>(event.button)); break;
    case InputEvent::Kind::Drag: queue.mouseMotion(x, y); break;
    case InputEvent::Kind::Release: queue.mouseButtonRelease(x, y, static_cast<unsigned>(event.button)); break;
    case InputEvent::Kind::Scroll: {
      const auto motion = event.scroll_steps > 0 ? osgGA::GUIEventAdapter::SCROLL_UP : osgGA::GUIEventAdapter::SCROLL_DOWN;
      for (int i = 0; i < (event.scroll_steps > 0 ? event.scroll_steps : -event.scroll_steps); ++i) queue.mouseScroll(motion);
      break;
    }
    case InputEvent::Kind::Key: queue.keyPress(event.key); break;
  }
}

}  // namespace mhd::viewer
