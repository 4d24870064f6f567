#pragma once
// `bench figures`: reruns the sweep behind every declared figure (FigureCatalog.h) and
// replots it from the CSV: OUT/<name>/data.csv (the rows), classes.csv (bottleneck figures),
// figure.png and figure.svg (tools/plot.py), summary.md (claim, seed, the rows as a table).
// --reduced runs each figure's small variant (the CI keeps the plotting path alive with it).
namespace sb {

class FiguresCommand {
public:
    /// argv[0] is "figures". Returns the exit code.
    static int main(int argc, char** argv);
};

} // namespace sb
