#pragma once
// `bench export IN.csv --format json|md|csv [-o OUT]`: a result CSV in the other formats (RowExport.h),
// to stdout or atomically to a file.
namespace sb {

class ExportCommand {
public:
    /// argv[0] is "export". Returns the exit code.
    static int main(int argc, char** argv);
};

} // namespace sb
