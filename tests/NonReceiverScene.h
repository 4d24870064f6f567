#pragma once
// The scene of the tests of ReceiverSplit::drawsApart (techniques/ReceiverSplit.h) on both APIs
// (tests/ShadowMapGLTest.cpp, tests/ShadowMapVkTest.cpp): a floor that receives and a ball over it that
// receives no shadow.
#include <string>

#include "TestSupport.h"

namespace sb::test {

// A scene whose non-receiver (a ball over the floor, "receives_shadow": false) is listed after the
// receiver, meshes and instances alike: the lighting pass draws it apart with a program that has no
// lookup (ReceiverSplit::drawsApart). Listed first, the draw order would change, so one program
// draws both: the control, which is what every scene got before. Directional light: the ball's shadow
// falls on the floor, and the ball (which casts) would shadow itself if it received.
inline std::string nonReceiverScene(bool receiverFirst) {
    const std::string floorMesh = R"({"name": "floor", "generator": "plane", "size": 10, "tessellation": 4})";
    const std::string ballMesh =
        R"({"name": "ball", "generator": "sphere", "radius": 0.7, "tessellation": 24})";
    const std::string floor =
        R"({"mesh": "floor", "position": [0, 0, 0], "color": [0.5, 0.5, 0.5], "casts_shadow": false})";
    const std::string ball =
        R"({"mesh": "ball", "position": [0, 2, 0], "color": [0.3, 0.4, 0.6], "receives_shadow": false})";
    const std::string name = receiverFirst ? "receiver_first" : "non_receiver_first";
    const std::string path = test::freshTestDir("shadowmap_" + name) + "/scene.json";
    test::writeFile(
        path,
        R"({"name": ")" + name + R"(", "meshes": [)" +
            (receiverFirst ? floorMesh + ", " + ballMesh : ballMesh + ", " + floorMesh) +
            R"(], "instances": [)" + (receiverFirst ? floor + ", " + ball : ball + ", " + floor) +
            R"(], "lights": [{"type": "directional", "direction": [0.4, -1, 0.2]}], "ambient": [0.2, 0.2, 0.2],
  "effects": ["hard_shadows"],
  "cameras": [{"name": "view", "eye": [0.5, 9, 0.001], "target": [0.5, 0, 0], "up": [0, 0, -1], "fov": 40,
               "near": 0.5, "far": 50}]})");
    return path;
}

// Every member of the family whose lighting pass looks its map up per fragment, as the tests of the split
// on both APIs run it (techniques/ReceiverSplit.h). Small maps: the image's equality is what is tested,
// not the shadow's accuracy.
inline const char* const kNonReceiverSplitSpecs[] = {"shadowmap",
                                                     "pcss:resolution=512",
                                                     "cubemap:resolution=256",
                                                     "paraboloid:resolution=512",
                                                     "cascaded:resolution=512",
                                                     "vsm:resolution=512",
                                                     "esm:resolution=512"};

} // namespace sb::test
