#pragma once
// The viewer's on-screen text (bench --window): lines of white text in the 5x7 bitmap font
// (bench/lib/font/BitmapFont.h) on a dimmed box in the window's top-left corner, and optionally the
// visibility view's colour bar (bench/lib/viewer/VisibilityView.h) as a legend below them.
//
// It draws into the default framebuffer after the frame has been blitted there, never into the frame
// targets the technique rendered, and restores the GL state it changes (gl/GlStateGuard.h):
// what the harness measures is the same frame with or without the overlay.
//
// Layout, in window pixels from the top-left, with s = scaleFor(width, height):
//   box:     from (kMargin, kMargin), kPadding * s inside on every side, black at kBoxOpacity over the
//            image (an image value v under the box shows as v * (1 - kBoxOpacity));
//   line i:  glyph cells BitmapFont::kCellWidth * s wide, the glyphs' top row at y = kMargin +
//            kPadding * s + i * kLineHeight * s, the first column at x = kMargin + kPadding * s; each
//            font pixel is an s x s square of pure white (255, 255, 255), drawn opaque.
// A line wider than the window is wrapped (after a ':' or ' ' where there is one); lines that do not
// fit the window's height are left out.
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "gl/ProgramCache.h"

namespace sb {

class Overlay {
public:
    static constexpr int kMargin = 8;          ///< box corner from the window's top-left corner (pixels)
    static constexpr int kPadding = 4;         ///< box edge to text, in font pixels
    static constexpr float kBoxOpacity = 0.6f; ///< the box: black at this opacity
    static constexpr int kLegendCells = 30;    ///< colour bar width, in character cells
    static constexpr int kLineHeight = 9;      ///< top to top of two lines, in font pixels: two blank rows
    /// Size of one font pixel in window pixels: 1 below 700 pixels on the window's shorter side, 2
    /// below 1400, then 3.
    static int scaleFor(int width, int height);
    /// `line` split into pieces of at most `maxChars` characters, each piece ending after the last ':'
    /// or ' ' that fits, or cut at maxChars where there is none. An empty line stays one empty piece.
    static std::vector<std::string> wrap(const std::string& line, size_t maxChars);

    /// Needs a current GL 4.5 context. The program (shaders/viewer/overlay.vert, overlay.frag) comes
    /// from `programs`, which must outlive the overlay.
    explicit Overlay(ProgramCache& programs);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    /// Draws `lines` (ASCII; others show as '?') and, when `legend`, the visibility colour bar with its
    /// labels after them, into the default framebuffer of `width` x `height` pixels.
    void draw(int width, int height, const std::vector<std::string>& lines, bool legend);

private:
    /// Looked up on every draw, never kept: the cache hands out references valid until it is cleared.
    const Program& program();

    ProgramCache& mPrograms;
    GLuint mAtlas = 0, mVertexArray = 0, mBuffer = 0;
};

} // namespace sb
