#include "render/label_font.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <imgui.h>

#include <cmath>

namespace vvi {

label_font::label_font() : atlas_(std::make_unique<ImFontAtlas>()) {
  font_ = atlas_->AddFontDefault();
  atlas_->GetTexDataAsAlpha8(&pixels_, &texture_width_, &texture_height_);
}

label_font::~label_font() = default;

void label_font::release() {
  if (texture_) glDeleteTextures(1, &texture_);
  texture_ = 0;
}

int label_font::line_height() const { return static_cast<int>(std::lround(font_->FontSize)); }

int label_font::width(const std::string& text) const {
  float x = 0;
  for (unsigned char c : text) x += font_->FindGlyph(static_cast<ImWchar>(c))->AdvanceX;
  return static_cast<int>(std::ceil(x));
}

void label_font::draw(const std::string& text, int x, int y, const rgb& ink, int height) const {
  if (!texture_) {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, texture_width_, texture_height_, 0, GL_ALPHA, GL_UNSIGNED_BYTE, pixels_);
    glPopClientAttrib();
  }
  // A model's render blocks find the state as they left it.
  glPushAttrib(GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_TEXTURE_BIT | GL_CURRENT_BIT);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);  // the ink's colour, the glyph's alpha
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor3f(ink[0], ink[1], ink[2]);
  glBegin(GL_QUADS);
  float pen = static_cast<float>(x);
  for (unsigned char c : text) {
    const ImFontGlyph* g = font_->FindGlyph(static_cast<ImWchar>(c));
    if (g->Visible) {
      // Whole pixels: the font's glyph boxes are, and so is the pen.
      float x0 = std::floor(pen + g->X0), x1 = x0 + (g->X1 - g->X0);
      float top = static_cast<float>(height - y) - std::floor(g->Y0), bottom = top - (g->Y1 - g->Y0);
      glTexCoord2f(g->U0, g->V1), glVertex2f(x0, bottom);
      glTexCoord2f(g->U1, g->V1), glVertex2f(x1, bottom);
      glTexCoord2f(g->U1, g->V0), glVertex2f(x1, top);
      glTexCoord2f(g->U0, g->V0), glVertex2f(x0, top);
    }
    pen += g->AdvanceX;
  }
  glEnd();
  glPopAttrib();
}

}  // namespace vvi
