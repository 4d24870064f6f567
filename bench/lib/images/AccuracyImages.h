#pragma once
// `bench accuracy --images DIR`: the pictures of one run, written into DIR and nowhere else.
//
// Per judged configuration (technique with its properties) and light L of scene S, with <t> its label
// (TechniqueSpec text, every character other than letters, digits and "._=+-" made '_'; a label seen
// before in the run gets "-2", "-3" ...):
//   S.<t>.lightL.technique.png  the technique's visibility of light L (8-bit grey, 0 black .. 1 white)
//   S.<t>.lightL.reference.png  the Embree reference's (no geometry black)
//   S.<t>.lightL.error.png      the error map (ErrorMap.h)
//   S.<t>.lightL.signed.png     where visibility is not binary: technique − reference (DifferenceMap.h,
//                               full scale ±1). Written when the technique declares soft shadows, the
//                               light has an extent (the reference is fractional), or some judged sample
//                               of the technique is fractional as an 8-bit picture shows it (rounds to
//                               1..254 of 255: filtered maps such as vsm, esm or a bilinear compare);
//                               a technique whose judged samples are all 0 or 1 has nothing to sign.
// and at the end one contact sheet, S.lightL.contact.png (ContactSheet.h): every configuration's error
// map under its label and figures (those of its CSV row), with a legend. Each file is written
// atomically (bench/lib/output/ImageWriter.h). S is sanitised like <t>.
#include <set>
#include <string>
#include <vector>

#include "bench/lib/images/ContactSheet.h"
#include "reference/AccuracyMetrics.h"

namespace sb {

class AccuracyImages {
public:
    /// The check before anything is measured: DIR is not empty and is a directory that can be written
    /// (a missing DIR is created when its parent folder exists; nothing above DIR is created). Leaves no
    /// file behind. Throws sb::Error(BadInput) naming `option` ("--images"), DIR and why.
    static void prepareDirectory(const std::string& dir, const std::string& option = "--images");
    /// `label` as it appears in file names.
    static std::string fileLabel(const std::string& label);
    /// The legend of every error map (the colours of ErrorMap.h and what each means).
    static std::vector<LegendEntry> legend();
    /// The contact sheet's header lines (what was judged: scene, light, reference, size).
    static std::vector<std::string> header(const std::string& scene, int light, bool softReference, int width,
                                           int height);
    /// The figures under a configuration's name on the contact sheet (its row's numbers).
    static std::vector<std::string> figures(const HardMetrics& hard, const SoftMetrics& soft,
                                            bool softTechnique);

    /// `width` x `height`: the judged frame's size.
    AccuracyImages(std::string dir, std::string scene, int light, int width, int height);

    /// One judged configuration: `technique`, `reference` (visibility of the light) and `mask` (1 =
    /// judged), bottom row first as read back; `hard`, `soft`: its row's figures; `softTechnique`: the
    /// technique declares soft shadows; `softReference`: the light has an extent, so the reference is
    /// fractional (AccuracyResult::softReference). Writes its files; returns their paths. The tile of
    /// the contact sheet is kept.
    std::vector<std::string> add(const std::string& label, const std::vector<float>& technique,
                                 const std::vector<float>& reference, const std::vector<uint8_t>& mask,
                                 const HardMetrics& hard, const SoftMetrics& soft, bool softTechnique,
                                 bool softReference);
    /// Whether some judged sample of `technique` is neither black nor white in an 8-bit picture.
    static bool fractional(const std::vector<float>& technique, const std::vector<uint8_t>& mask);
    /// Writes the contact sheet of every configuration added so far; returns its path ("" when none
    /// was added).
    std::string writeContactSheet() const;
    /// The contact sheet's path.
    std::string contactSheetPath() const;

private:
    std::string path(const std::string& label, const std::string& kind) const;
    std::string mDir, mScene;
    int mLight = 0;
    bool mSoftReference = false;
    int mWidth = 0, mHeight = 0;
    std::set<std::string> mLabels;
    std::vector<ContactTile> mTiles;
};

} // namespace sb
