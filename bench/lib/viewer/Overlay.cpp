#include "bench/lib/viewer/Overlay.h"

#include <algorithm>
#include <cstddef>

#include "bench/lib/font/BitmapFont.h"
#include "gl/GlStateGuard.h"

namespace sb {

namespace {

struct Vertex {
    float x, y, u, v, mode;
};

void quad(std::vector<Vertex>& out, float x0, float y0, float x1, float y1, float u0, float v0, float u1,
          float v1, float mode) {
    const Vertex a{x0, y0, u0, v0, mode}, b{x1, y0, u1, v0, mode}, c{x1, y1, u1, v1, mode},
        d{x0, y1, u0, v1, mode};
    out.insert(out.end(), {a, b, c, a, c, d});
}

void text(std::vector<Vertex>& out, const std::string& line, int x, int y, int s) {
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == ' ') continue;
        const char shown = (c < BitmapFont::kFirst || c > BitmapFont::kLast) ? '?' : c;
        const float u0 = float((shown - BitmapFont::kFirst) * BitmapFont::kGlyphWidth);
        const float px = float(x + int(i) * BitmapFont::kCellWidth * s);
        quad(out, px, float(y), px + float(BitmapFont::kGlyphWidth * s),
             float(y + BitmapFont::kGlyphHeight * s), u0, 0.0f, u0 + float(BitmapFont::kGlyphWidth),
             float(BitmapFont::kGlyphHeight), 1.0f);
    }
}
} // namespace

int Overlay::scaleFor(int width, int height) {
    return std::clamp(std::min(width, height) / 700 + 1, 1, 3);
}

std::vector<std::string> Overlay::wrap(const std::string& line, size_t maxChars) {
    maxChars = std::max<size_t>(maxChars, 1);
    std::vector<std::string> pieces;
    size_t start = 0;
    while (line.size() - start > maxChars) {
        size_t cut = line.find_last_of(": ", start + maxChars - 1);
        cut = (cut == std::string::npos || cut < start) ? start + maxChars : cut + 1;
        pieces.push_back(line.substr(start, cut - start));
        start = cut;
    }
    pieces.push_back(line.substr(start));
    return pieces;
}

const Program& Overlay::program() {
    return mPrograms.get({"viewer/overlay.vert", "viewer/overlay.frag", ""}, {});
}

Overlay::Overlay(ProgramCache& programs) : mPrograms(programs) {
    program(); // compile now: a shader error shows when the viewer opens

    const std::vector<uint8_t> atlas = BitmapFont::atlas();
    GLint unpackAlignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1); // rows of 95 * 5 bytes
    glCreateTextures(GL_TEXTURE_2D, 1, &mAtlas);
    glTextureStorage2D(mAtlas, 1, GL_R8, BitmapFont::kGlyphCount * BitmapFont::kGlyphWidth,
                       BitmapFont::kGlyphHeight);
    glTextureSubImage2D(mAtlas, 0, 0, 0, BitmapFont::kGlyphCount * BitmapFont::kGlyphWidth,
                        BitmapFont::kGlyphHeight, GL_RED, GL_UNSIGNED_BYTE, atlas.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment);

    glCreateBuffers(1, &mBuffer);
    glCreateVertexArrays(1, &mVertexArray);
    glVertexArrayVertexBuffer(mVertexArray, 0, mBuffer, 0, sizeof(Vertex));
    const GLuint offsets[3] = {offsetof(Vertex, x), offsetof(Vertex, u), offsetof(Vertex, mode)};
    const GLint sizes[3] = {2, 2, 1};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(mVertexArray, a);
        glVertexArrayAttribFormat(mVertexArray, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(mVertexArray, a, 0);
    }
}

Overlay::~Overlay() {
    glDeleteVertexArrays(1, &mVertexArray);
    glDeleteBuffers(1, &mBuffer);
    glDeleteTextures(1, &mAtlas);
}

void Overlay::draw(int width, int height, const std::vector<std::string>& lines, bool legend) {
    if (width <= 0 || height <= 0) return;
    const int s = scaleFor(width, height);
    const int inset = kMargin + kPadding * s;
    const int cell = BitmapFont::kCellWidth * s, lineHeight = kLineHeight * s;
    // Characters that fit between the insets: n cells less the last one's blank column.
    const int available = width - 2 * inset;
    const size_t maxChars = size_t(std::max(1, (available + s) / cell));
    const int maxRows = std::max(0, (height - 2 * inset + 2 * s) / lineHeight);

    std::vector<std::string> rows;
    for (const std::string& line : lines)
        for (std::string& piece : wrap(line, maxChars)) rows.push_back(std::move(piece));
    int legendRow = -1;
    if (legend) {
        // The bar takes a row of its own; the labels put 0 and 1 under its two ends.
        const size_t cells = std::min<size_t>(kLegendCells, maxChars);
        legendRow = int(rows.size());
        rows.push_back(std::string(cells, ' '));
        std::string labels = "0 shadowed";
        const std::string right = "lit 1";
        labels +=
            std::string(cells > labels.size() + right.size() ? cells - labels.size() - right.size() : 1, ' ');
        rows.push_back(labels + right);
        rows.push_back("NaN: magenta, out of [0,1]: green");
    }
    if (int(rows.size()) > maxRows) rows.resize(size_t(maxRows));
    if (rows.empty()) return;

    int textWidth = 0;
    for (const std::string& r : rows) textWidth = std::max(textWidth, BitmapFont::textWidth(r, s));
    std::vector<Vertex> vertices;
    const int boxRight = inset + textWidth + kPadding * s;
    const int boxBottom =
        inset + int(rows.size()) * lineHeight - (lineHeight - BitmapFont::kGlyphHeight * s) + kPadding * s;
    quad(vertices, float(kMargin), float(kMargin), float(boxRight), float(boxBottom), 0, 0, 0, 0, 0.0f);
    for (size_t i = 0; i < rows.size(); ++i) {
        const int y = inset + int(i) * lineHeight;
        if (int(i) == legendRow) {
            const int barWidth = BitmapFont::textWidth(rows[i], s);
            quad(vertices, float(inset), float(y), float(inset + barWidth),
                 float(y + BitmapFont::kGlyphHeight * s), 0.0f, 0.0f, 1.0f, 0.0f, 2.0f);
        } else {
            text(vertices, rows[i], inset, y, s);
        }
    }

    GlStateGuard guard;
    glNamedBufferData(mBuffer, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STREAM_DRAW);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    const Program& p = program();
    p.use();
    glUniform2f(p.uniform("uWindowSize"), float(width), float(height));
    glUniform1f(p.uniform("uBoxOpacity"), kBoxOpacity);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mAtlas);
    glBindVertexArray(mVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
}

} // namespace sb
