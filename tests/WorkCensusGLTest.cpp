// The exact work per pass (bench/lib/harness/WorkCensus.h), layer A of the perf gate. Independent answers:
// the passes must sum to one pipeline-statistics query wrapped around the whole frame (the census frame as it
// was measured before passes were split), every pass's primitives are known from the scene (each pass of
// `volume` and `shadowmap` draws a known set), and the counts repeat exactly.
#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "gl/PipelineStatistics.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

constexpr int kSize = 96;

const PassWork* find(const FrameWork& work, const std::string& pass) {
    for (const auto& [name, w] : work)
        if (name == pass) return &w;
    return nullptr;
}

TEST(WorkCensusGLTest, PassesSumToOneWholeFrameQueryAndRepeatExactly) {
    for (const char* technique : {"none", "shadowmap", "volume", "occluder", "proxy", "projective:blur=2"}) {
        SCOPED_TRACE(technique);
        Harness h(test::quickConfig("aircraft", "mid", kSize));
        auto t = TechniqueRegistry::create(TechniqueSpec::parse(technique));
        h.prepare(*t);
        const FrameLoads census = h.measureLoads(*t);
        ASSERT_TRUE(census.pipeline) << "llvmpipe has GL_ARB_pipeline_statistics_query";
        // The whole frame under one set of queries, no observer.
        PipelineStatistics whole;
        whole.begin();
        h.renderFrame(*t);
        const PipelineCounts w = whole.end();
        EXPECT_EQ(census.pipeline->fragmentShaderInvocations, w.fragmentShaderInvocations);
        EXPECT_EQ(census.pipeline->primitivesSubmitted, w.primitivesSubmitted);
        EXPECT_EQ(census.pipeline->clippingOutputPrimitives, w.clippingOutputPrimitives);
        EXPECT_EQ(census.pipeline->vertexShaderInvocations, w.vertexShaderInvocations);
        const FrameLoads again = h.measureLoads(*t);
        ASSERT_EQ(again.passes.size(), census.passes.size());
        for (size_t i = 0; i < census.passes.size(); ++i) {
            EXPECT_EQ(again.passes[i].first, census.passes[i].first);
            EXPECT_EQ(again.passes[i].second.pipeline->fragmentShaderInvocations,
                      census.passes[i].second.pipeline->fragmentShaderInvocations);
            EXPECT_EQ(again.passes[i].second.submitted.glCalls, census.passes[i].second.submitted.glCalls);
        }
    }
}

TEST(WorkCensusGLTest, EachPassCountsWhatItDraws) {
    Harness h(test::quickConfig("aircraft", "mid", kSize));
    const uint64_t sceneTriangles = h.scene().totalTriangles();
    auto none = TechniqueRegistry::create(TechniqueSpec::parse("none"));
    h.prepare(*none);
    const FrameLoads n = h.measureLoads(*none);
    ASSERT_EQ(n.passes.size(), 1u); // "lighting" only: the frame's clear counts nothing
    EXPECT_EQ(n.passes[0].first, "lighting");
    EXPECT_EQ(n.passes[0].second.pipeline->primitivesSubmitted, sceneTriangles);
    EXPECT_EQ(n.passes[0].second.submitted.triangles, sceneTriangles);

    auto sm = TechniqueRegistry::create(TechniqueSpec::parse("shadowmap"));
    h.prepare(*sm);
    const FrameLoads s = h.measureLoads(*sm);
    const PassWork* depth = find(s.passes, "depth");
    const PassWork* lighting = find(s.passes, "lighting");
    ASSERT_TRUE(depth && lighting);
    // The lit pass draws the whole scene; the depth pass the casters only, which is what its submitter
    // statistics say it issued, primitive for primitive.
    EXPECT_EQ(lighting->pipeline->primitivesSubmitted, sceneTriangles);
    EXPECT_EQ(depth->pipeline->primitivesSubmitted, depth->submitted.triangles);
    EXPECT_LT(depth->submitted.triangles, sceneTriangles);
    EXPECT_GT(depth->pipeline->fragmentShaderInvocations, 0u);
}

} // namespace
