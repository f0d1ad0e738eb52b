#include "viewer/hud_overlay.h"

#include "viewer/osg_convert.h"

#include <osg/Depth>
#include <osg/Geode>

#include <osgText/Font>

#include <algorithm>
#include <filesystem>

namespace mhd::viewer {
namespace {

// OSG's built-in font loses '.' and ':' at small sizes; DejaVu (fonts-dejavu-core, which
// fontconfig pulls in) keeps them. Without the file the built-in font is used.
constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";

}  // namespace

HudOverlay::HudOverlay(int width_px, int height_px)
    : camera_(make_ref<osg::Camera>()), text_(make_ref<osgText::Text>()) {
  camera_->setName("hud");
  camera_->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
  camera_->setProjectionMatrixAsOrtho2D(0.0, width_px, 0.0, height_px);
  camera_->setViewMatrix(osg::Matrixd::identity());
  // Nested: drawn inside the eye camera's stage, after the scene (bin 100), no clearing.
  camera_->setRenderOrder(osg::Camera::NESTED_RENDER);
  camera_->setClearMask(0);
  camera_->setAllowEventFocus(false);
  osg::StateSet* s = camera_->getOrCreateStateSet();
  s->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
  s->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
  s->setRenderBinDetails(100, "RenderBin");

  const float size_px = std::clamp(static_cast<float>(height_px) / 30.0f, 12.0f, 22.0f);
  text_->setCharacterSize(size_px);
  if (std::filesystem::exists(kFontFile)) {
    if (osg::ref_ptr<osgText::Font> font = osgText::readRefFontFile(kFontFile)) {
      text_->setFont(font.get());
      const auto resolution = static_cast<unsigned>(size_px);
      text_->setFontResolution(resolution, resolution);
    }
  }
  text_->setAlignment(osgText::Text::LEFT_TOP);
  text_->setPosition(osg::Vec3(10.0f, static_cast<float>(height_px) - 10.0f, 0.0f));
  text_->setColor(osg::Vec4(0.95f, 0.95f, 0.95f, 1.0f));
  text_->setBackdropType(osgText::Text::OUTLINE);
  text_->setBackdropColor(osg::Vec4(0.0f, 0.0f, 0.0f, 1.0f));
  text_->setDataVariance(osg::Object::DYNAMIC);
  auto geode = make_ref<osg::Geode>();
  geode->addDrawable(text_.get());
  camera_->addChild(geode.get());
}

void HudOverlay::set_text(const std::string& text) { text_->setText(text); }

}  // namespace mhd::viewer
