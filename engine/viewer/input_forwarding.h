#pragma once
// Internal to mhd_viewer (includes OSG): OSG's mouse and key events to InputEvent and
// back. The forwarder hands the window's events to a callback; push_input_event puts an
// InputEvent into the viewer's own event queue, so scripted input takes the same path
// through OSG's event traversal as the user's.

#include "viewer/input_event.h"

#include <osgGA/EventQueue>
#include <osgGA/GUIEventHandler>

#include <functional>

namespace mhd::viewer {

class InputForwarder : public osgGA::GUIEventHandler {
 public:
  explicit InputForwarder(std::function<void(const InputEvent&)> handler) : handler_(std::move(handler)) {}
  bool handle(const osgGA::GUIEventAdapter& event, osgGA::GUIActionAdapter& action) override;
  using osgGA::GUIEventHandler::handle;

 private:
  std::function<void(const InputEvent&)> handler_;
};

/// Queues `event` as OSG would for a window of width_px x height_px.
void push_input_event(osgGA::EventQueue& queue, const InputEvent& event, int width_px, int height_px);

}  // namespace mhd::viewer
