#pragma once
// PNG output (core/PngFile): --screenshot (colour) and --visibility (the visibility target), and the
// one write path of every other picture (goldens, error maps, contact sheets).
#include <string>
#include <vector>

#include "gl/FrameTargets.h"

namespace sb {

class ImageWriter {
public:
    /// Colour attachment as 8-bit RGB, top row first. Throws sb::Error naming the path on failure.
    static void writeColor(const FrameTargets& targets, const std::string& path);
    /// Visibility of light `light` as 8-bit grey (1 lit = white, 0 shadowed = black; values clamped).
    static void writeVisibility(const FrameTargets& targets, int light, const std::string& path);
    /// The same from pixels already read back (either API's targets: rows bottom-up, RGBA8 colour and
    /// 4 floats of visibility per pixel).
    static void writeColor(int width, int height, const std::vector<unsigned char>& rgba,
                           const std::string& path);
    static void writeVisibility(int width, int height, const std::vector<float>& visibility, int light,
                                const std::string& path);
    /// The up-front check of an image output (`option` names it in the message): a `.png` name, a
    /// regular file or nothing, in a writable directory. Throws sb::Error(BadInput).
    static void checkWritable(const std::string& path, const std::string& option);
    /// Writes `channels` x 8-bit pixels (top row first) to `path` as PNG, atomically (PngFile::write):
    /// the image goes to "<path>.tmp" in the same folder, every write, the flush and the close checked,
    /// and is renamed over `path`, so a reader never sees half a picture, a kill leaves the old image or
    /// the new one, and a failed write (a full disk) leaves the old file untouched and no temporary
    /// file. Throws sb::Error(Failure) naming the path, the temporary file and the OS reason, as the CSV
    /// writer does. The one way the bench writes a picture (screenshots, visibility, goldens, maps).
    static void writeAtomic(const std::string& path, int width, int height, int channels,
                            const unsigned char* pixels);
};

} // namespace sb
