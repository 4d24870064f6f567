# Sourced by scripts/sanitize.sh and scripts/test.sh: the tests that never run under the sanitizers,
# as one ctest regular expression, SB_SANITIZE_LEFT_OUT. sanitize.sh passes it to ctest's -E; test.sh
# uses it the other way round: the cli tests it does not match run under ASan anyway (sanitize.sh's cli
# label: the release build's test programs against build-asan/bench), so test.sh's release ctest leaves
# those out and runs only the cli tests matched here.
#
# Cli.WindowViewerRendersAndQuits (the GLFW window on Xvfb). Its leaks are allocated inside
# the GLX driver that Mesa dlcloses before exit, so LeakSanitizer sees "<unknown module>" frames and no
# suppression can name the library; the same test runs in the normal build.
# handshadow switches LeakSanitizer off for itself (bench/handwritten/handshadow/HandShadow.cpp says why); ASan and
# UBSan still run in it.
# Also left out, because the code they drive is not ours to sanitize and they cost CI minutes under
# ASan: PlotCli, ReportCli and ReportCliNames (Python's matplotlib and headless Chromium; bench report only starts
# the script), PackageCliTest (cmake, dpkg-deb and lintian), DocsCommandsCli (the documents' commands:
# 174 s under ASan, every code path they reach is run under ASan by the other cli tests) and FiguresCli (about 140 s here: its
# sweeps' code paths run under ASan in SweepCli, its plots are Python). All of them run in the normal build.
# And the vertex- and fill-bound cases of Synthetic/KnownBottleneck, on GL and on Vulkan: the classifier reads wall times, and
# under ASan the harness's own code runs several times slower, which moves time into the CPU stage those
# workloads must not show (a run of 2026-12-05: vertex classed "cpu", fit residual 60%). The study's code
# still runs under ASan in the CPU-bound case, which ASan leaves CPU-bound; all three are held in the
# normal build.
# And DriverCli and BisectCli: the first loads a second Mesa build into bench processes (the driver's
# code, not ours; our driver table runs under ASan in DriverTableTest, and a driver's environment in the
# perf gate's A/B case), the second checks git's and the option parser's refusals, which other cli tests
# run under ASan. Both run in the normal build.
# And the tests that bound a bench process's peak memory or run it under `ulimit -v`: SceneMemoryCli and
# LargeCsvCliTest's export, compare and append bounds. ASan reserves terabytes of address space for its
# shadow at start (which `ulimit -v` refuses) and keeps freed blocks in a 256 MiB quarantine, so a peak
# under ASan measures the sanitizer (a streamed export peaked at 520 MiB under ASan, 70 MiB without).
# Their code paths run under ASan in CsvWriterTest, CsvMergeTest, SceneLoaderTest and ModelLoaderTest;
# the bounds are held in the normal build.
# And the per-row Vulkan tables (Table/HardCasesVulkan, Techniques/GlVulkanImage: a GL and a Vulkan
# frame and an Embree trace per row, about 3 s each under ASan, 120 rows): instead, the step after
# ctest runs every technique's Vulkan form once per submission mode in one ASan bench process with the
# validation layer on, which reaches the same recording code; the tables run in the normal build.
SB_SANITIZE_LEFT_OUT='^Table/HardCasesVulkan\.|^Techniques/GlVulkanImage\.|^Cli\.WindowViewerRendersAndQuits$|^PlotCli\.|^ReportCli\.|^ReportCliNames\.|^PackageCliTest\.|^DocsCommandsCli\.|^FiguresCli\.|^DriverCli\.|^BadInput/BisectCli\.|^Synthetic/KnownBottleneck\.IsNamedCorrectly/(vulkan_)?(vertex|fill)|^SceneMemoryCli\.|^LargeCsvCliTest\.(JsonExportStreams|GoogleBenchmarkExportStreams|CompareKeepsOnlyTheColumnsItNeeds|AppendingOneRowDoesNotRewriteTheFile)$'
export SB_SANITIZE_LEFT_OUT
