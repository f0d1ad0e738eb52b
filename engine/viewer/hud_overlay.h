#pragma once
// Internal to mhd_viewer (includes OSG): lines of text over the image, top left, in
// window pixels. A nested camera drawn last in the eye camera's own render stage, so a
// screenshot (read when the eye camera finishes) contains it.

#include <osg/Camera>
#include <osg/ref_ptr>
#include <osgText/Text>

#include <string>

namespace mhd::viewer {

class HudOverlay {
 public:
  HudOverlay(int width_px, int height_px);
  [[nodiscard]] osg::Node* root() const { return camera_.get(); }
  void set_text(const std::string& text);

 private:
  osg::ref_ptr<osg::Camera> camera_;
  osg::ref_ptr<osgText::Text> text_;
};

}  // namespace mhd::viewer
