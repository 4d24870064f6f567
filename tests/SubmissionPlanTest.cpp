// Unit tests of techniques/SubmissionPlan: the plan both APIs' submitters upload and draw, for a scene of
// two meshes and five instances with mixed shadow flags. Every expected batch, record, id and run below
// is worked out by hand from the scene's table (the comments show the working), not by the plan's code.
#include <gtest/gtest.h>

#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

#include "techniques/SubmissionPlan.h"

using namespace sb;

namespace {

/// The test scene, in scene order: mesh, casts, receives, object id.
struct InstanceRow {
    uint32_t mesh;
    bool casts;
    bool receives;
    uint32_t objectId;
};
constexpr InstanceRow kInstances[] = {
    {1, true, true, 1},  // 0
    {0, true, false, 2}, // 1: casts, receives none
    {1, false, true, 3}, // 2: casts none (a ground)
    {0, true, true, 4},  // 3
    {1, true, false, 5}, // 4: casts, receives none
};

/// A model matrix told apart by its translation: x = 10 * instance + 1.
glm::mat4 modelOf(size_t instance) {
    glm::mat4 m(1.0f);
    m[3] = glm::vec4(10.0f * float(instance) + 1.0f, 2.0f, 3.0f, 1.0f);
    return m;
}

Scene handScene() {
    Scene scene;
    Mesh a; // one triangle
    a.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    a.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    a.indices = {0, 1, 2};
    Mesh b; // two triangles
    b.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    b.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    b.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes = {a, b};
    for (size_t i = 0; i < std::size(kInstances); ++i) {
        Instance inst;
        inst.mesh = kInstances[i].mesh;
        inst.castsShadow = kInstances[i].casts;
        inst.receivesShadow = kInstances[i].receives;
        inst.objectId = kInstances[i].objectId;
        inst.color = glm::vec3(0.1f * float(i), 0.5f, 0.25f);
        inst.model = modelOf(i);
        scene.instances.push_back(inst);
    }
    return scene;
}

using Batch = SubmissionPlan::Batch;
using Run = std::pair<uint32_t, uint32_t>; ///< (first record, count)

/// The records, set by set, meshes in scene order, instances in scene order within a mesh:
///   All          mesh 0: 1 3      mesh 1: 0 2 4   records  0..4
///   Casters      mesh 0: 1 3      mesh 1: 0 4     records  5..8
///   Receivers    mesh 0: 3        mesh 1: 0 2     records  9..11
///   NonCasters   mesh 0: (none)   mesh 1: 2       record  12
///   NonReceivers mesh 0: 1        mesh 1: 4       records 13..14
constexpr uint32_t kRecordInstance[] = {1, 3, 0, 2, 4, 1, 3, 0, 4, 3, 0, 2, 2, 1, 4};

const struct {
    const char* name;
    DrawSet set;
    std::vector<Batch> batches; ///< mesh, first, count
} kBatchData[] = {
    {"All", DrawSet::All, {{0, 0, 2}, {1, 2, 3}}},
    {"Casters", DrawSet::Casters, {{0, 5, 2}, {1, 7, 2}}},
    {"Receivers", DrawSet::Receivers, {{0, 9, 1}, {1, 10, 2}}},
    {"NonCasters", DrawSet::NonCasters, {{1, 12, 1}}},
    {"NonReceivers", DrawSet::NonReceivers, {{0, 13, 1}, {1, 14, 1}}},
};

std::vector<Run> runsOf(const SubmissionPlan& plan, const Batch& batch, InstanceMask keep) {
    std::vector<Run> runs;
    plan.forEachKeptRun(batch, keep,
                        [&](uint32_t first, uint32_t count) { runs.emplace_back(first, count); });
    return runs;
}

} // namespace

TEST(SubmissionPlan, InterleavedVerticesArePositionThenNormal) {
    const Scene scene = handScene();
    const Mesh& b = scene.meshes[1];
    const std::vector<glm::vec3> v = interleavedVertices(b);
    ASSERT_EQ(v.size(), 8u);
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(v[2 * i], b.positions[i]) << "vertex " << i;
        EXPECT_EQ(v[2 * i + 1], b.normals[i]) << "vertex " << i;
    }
    EXPECT_EQ(kVertexStride, 24u);
    EXPECT_EQ(kNormalOffset, 12u);
}

TEST(SubmissionPlan, InstancesByMeshKeepSceneOrderWithinAMesh) {
    // Mesh 0 holds instances 1 and 3, mesh 1 holds 0, 2 and 4.
    EXPECT_EQ(instancesByMesh(handScene()), (std::vector<uint32_t>{1, 3, 0, 2, 4}));
}

TEST(SubmissionPlan, RecordLayoutIsWhatInstanceGlslReads) {
    // Attributes 4..7: four vec4 columns at 0, 16, 32, 48; attribute 8 at 64; stride 80.
    EXPECT_EQ(sizeof(InstanceRecord), 80u);
    EXPECT_EQ(offsetof(InstanceRecord, model), 0u);
    EXPECT_EQ(offsetof(InstanceRecord, colorId), 64u);
}

TEST(SubmissionPlan, BatchesPerSetAndMesh) {
    const SubmissionPlan plan(handScene());
    for (const auto& data : kBatchData) {
        SCOPED_TRACE(data.name);
        const std::span<const Batch> got = plan.batches(data.set);
        ASSERT_EQ(got.size(), data.batches.size());
        for (size_t i = 0; i < got.size(); ++i) {
            EXPECT_EQ(got[i].mesh, data.batches[i].mesh) << "batch " << i;
            EXPECT_EQ(got[i].first, data.batches[i].first) << "batch " << i;
            EXPECT_EQ(got[i].count, data.batches[i].count) << "batch " << i;
        }
    }
}

TEST(SubmissionPlan, RecordsHoldTheirInstanceWithShadowSignedIds) {
    const SubmissionPlan plan(handScene());
    // The w of each record, from the table: instances 1 and 4 receive no shadow, so their ids (2, 5)
    // are negated; the others keep theirs (0 -> 1, 2 -> 3, 3 -> 4).
    constexpr float kSignedId[] = {-2, 4, 1, 3, -5, -2, 4, 1, -5, 4, 1, 3, 3, -2, -5};
    ASSERT_EQ(plan.records().size(), std::size(kRecordInstance));
    for (uint32_t r = 0; r < std::size(kRecordInstance); ++r) {
        const uint32_t i = kRecordInstance[r];
        EXPECT_EQ(plan.instanceOf(r), i) << "record " << r;
        const InstanceRecord& rec = plan.records()[r];
        EXPECT_EQ(rec.model, modelOf(i)) << "record " << r;
        EXPECT_EQ(rec.colorId, glm::vec4(0.1f * float(i), 0.5f, 0.25f, kSignedId[r])) << "record " << r;
    }
}

TEST(SubmissionPlan, InstancesMovedRewritesEveryRecordOfAnInstance) {
    Scene scene = handScene();
    SubmissionPlan plan(scene);
    glm::mat4 moved(2.0f);
    moved[3] = glm::vec4(-7.0f, 0.0f, 0.0f, 1.0f);
    scene.instances[4].model = moved;
    plan.instancesMoved(scene);
    // Instance 4 is in All, Casters and NonReceivers: records 4, 8 and 14.
    for (uint32_t r = 0; r < std::size(kRecordInstance); ++r) {
        const bool isFour = r == 4 || r == 8 || r == 14;
        EXPECT_EQ(plan.records()[r].model, isFour ? moved : modelOf(kRecordInstance[r])) << "record " << r;
    }
    // Colour and id stay as built.
    EXPECT_EQ(plan.records()[14].colorId, glm::vec4(0.1f * 4.0f, 0.5f, 0.25f, -5.0f));
}

namespace {
constexpr uint8_t kAll[] = {1, 1, 1, 1, 1};
constexpr uint8_t kNoTwo[] = {1, 1, 0, 1, 1};       // culls the middle of mesh 1's All batch
constexpr uint8_t kNoZero[] = {0, 1, 1, 1, 1};      // culls the head of mesh 1's batches
constexpr uint8_t kOnlyThree[] = {0, 0, 0, 1, 0};   // one instance of mesh 0 left
constexpr uint8_t kZeroAndFour[] = {1, 0, 0, 0, 1}; // mesh 0 culled whole

const struct {
    const char* name;
    DrawSet set;
    InstanceMask keep;
    std::vector<std::vector<Run>> runs; ///< per batch of the set, (first record, count)
} kRunData[] = {
    {"unmasked All", DrawSet::All, {}, {{{0, 2}}, {{2, 3}}}},
    {"mask keeping all", DrawSet::All, kAll, {{{0, 2}}, {{2, 3}}}},
    // Mesh 1's All records 2, 3, 4 hold instances 0, 2, 4: dropping 2 splits the batch in two.
    {"hole splits a batch", DrawSet::All, kNoTwo, {{{0, 2}}, {{2, 1}, {4, 1}}}},
    // Casters of mesh 1 (records 7, 8: instances 0, 4) do not hold instance 2: one run.
    {"hole outside the set", DrawSet::Casters, kNoTwo, {{{5, 2}}, {{7, 2}}}},
    // Receivers of mesh 1 (records 10, 11: instances 0, 2): only 10 left.
    {"tail culled", DrawSet::Receivers, kNoTwo, {{{9, 1}}, {{10, 1}}}},
    {"head culled", DrawSet::All, kNoZero, {{{0, 2}}, {{3, 2}}}},
    // NonCasters' one batch holds instance 2 only: no run.
    {"batch culled whole", DrawSet::NonCasters, kNoTwo, {{}}},
    {"one instance left", DrawSet::All, kOnlyThree, {{{1, 1}}, {}}},
    {"first mesh culled", DrawSet::NonReceivers, kZeroAndFour, {{}, {{14, 1}}}},
};
} // namespace

TEST(SubmissionPlan, KeptRunsUnderAMask) {
    const SubmissionPlan plan(handScene());
    for (const auto& data : kRunData) {
        SCOPED_TRACE(data.name);
        const std::span<const Batch> batches = plan.batches(data.set);
        ASSERT_EQ(batches.size(), data.runs.size());
        for (size_t b = 0; b < batches.size(); ++b)
            EXPECT_EQ(runsOf(plan, batches[b], data.keep), data.runs[b]) << "batch " << b;
    }
}

TEST(SubmissionPlan, EmptySceneHasNoRecordsOrBatches) {
    const SubmissionPlan plan{Scene{}};
    EXPECT_TRUE(plan.records().empty());
    for (size_t s = 0; s < kDrawSetCount; ++s) EXPECT_TRUE(plan.batches(DrawSet(s)).empty());
}
