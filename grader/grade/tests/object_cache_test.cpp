// The grader's cache of compiled objects (grader/grade/object_cache.h): an object comes back only
// when everything its compile read is as it was. Each case compiles a small file of a work folder
// laid out as a grade's (include/, submission/stages/...) with the compiler the build uses.

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/testing/catch.h"
#include "grader/grade/object_cache.h"
#include "grader/sandbox/tests/sandbox_test_support.h"

using namespace raystep::grade;
using raystep::grade::testing::read_text;
using raystep::grade::testing::TempFolder;

namespace fs = std::filesystem;

namespace {

void write(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

// A work folder with a header of the grader's and a stage of two files, the first of which
// includes a header of the submission's own.
struct Work {
    TempFolder folder{0755};
    fs::path work = folder.path() / "work";
    fs::path stage = work / "submission/stages/1_vectors";
    fs::path source = stage / "vectors.cpp";
    fs::path objects = work / "objects";
    ProbeToolchain toolchain;

    Work() {
        toolchain.compiler = RAYSTEP_CXX_COMPILER;
        toolchain.compile_flags = {"-O0", "-std=c++17"};
        write(work / "include/base/answer.h", "inline int answer() { return 42; }\n");
        write(source,
              "#include \"base/answer.h\"\n#include \"helper.h\"\nint f() { return "
              "answer() + helper(); }\n");
        write(stage / "helper.h", "inline int helper() { return 1; }\n");
        write(stage / "other.cpp", "int g() { return 2; }\n");
        fs::create_directories(objects);
    }

    // Compiles the stage's first file to OBJECTS/NAME.o, listing what it read as keep() wants.
    fs::path compile(const std::string& name) const {
        const fs::path object = objects / (name + ".o");
        std::string command = toolchain.compiler.string();
        for (const std::string& flag : toolchain.compile_flags)
            command += " " + flag;
        command += " -I" + (work / "include").string() + " -c " + source.string() + " -o " +
                   object.string();
        for (const std::string& flag : ObjectCache::dependency_flags(object))
            command += " " + flag;
        REQUIRE(std::system(command.c_str()) == 0);
        return object;
    }

    ObjectCache cache() const { return ObjectCache(folder.path() / "cache", toolchain, work); }

    // A precompiled header as the grader's build makes one, placed in work/precompiled as the
    // probe builder places it, and taken first by every compile from then on.
    void precompile_header() {
        const fs::path built = folder.path() / "build/probe_precompiled.h";
        write(built, "inline int base() { return 40; }\n");
        std::string command = toolchain.compiler.string();
        for (const std::string& flag : toolchain.compile_flags)
            command += " " + flag;
        command += " -x c++-header " + built.string() + " -o " + built.string() + ".gch";
        REQUIRE(std::system(command.c_str()) == 0);
        toolchain.precompiled_header = built;
        const fs::path placed = work / "precompiled/probe_precompiled.h";
        fs::create_directories(placed.parent_path());
        fs::copy_file(built, placed);
        fs::copy_file(built.string() + ".gch", placed.string() + ".gch");
        toolchain.compile_flags.insert(toolchain.compile_flags.end(),
                                       {"-include", placed.string()});
    }
};

}  // namespace

TEST_CASE("an object kept is taken again, the same bytes, while nothing it read has changed",
          "[grader]") {
    Work w;
    const fs::path compiled = w.compile("first");
    w.cache().keep(w.source, compiled);
    const fs::path taken = w.objects / "taken.o";
    REQUIRE(w.cache().take(w.source, taken));
    CHECK(read_text(taken) == read_text(compiled));
    // A file of the stage that the compile did not read changes nothing.
    write(w.stage / "other.cpp", "int g() { return 3; }\n");
    CHECK(w.cache().take(w.source, w.objects / "again.o"));
}

TEST_CASE(
    "an object is not taken when its file, a file of the submission it read, a header or "
    "the flags differ",
    "[grader]") {
    Work w;
    w.cache().keep(w.source, w.compile("first"));
    const fs::path taken = w.objects / "taken.o";

    SECTION("the compiled file") {
        write(w.source, read_text(w.source) + "int h() { return 0; }\n");
        CHECK_FALSE(w.cache().take(w.source, taken));
    }
    SECTION("a file of the submission that it includes") {
        write(w.stage / "helper.h", "inline int helper() { return 2; }\n");
        CHECK_FALSE(w.cache().take(w.source, taken));
    }
    SECTION("a header of the grader's") {
        write(w.work / "include/base/answer.h", "inline int answer() { return 41; }\n");
        CHECK_FALSE(w.cache().take(w.source, taken));
    }
    SECTION("the compiler's flags") {
        w.toolchain.compile_flags.push_back("-DNDEBUG");
        CHECK_FALSE(w.cache().take(w.source, taken));
    }
    CHECK_FALSE(fs::exists(taken));
}

TEST_CASE(
    "an entry is compared byte for byte, so one whose recorded inputs differ from the file's "
    "is not taken, whatever its folder's name",
    "[grader]") {
    Work w;
    w.cache().keep(w.source, w.compile("first"));
    // Every entry's record, altered as a file that merely hashed alike would differ.
    for (const fs::directory_entry& entry : fs::directory_iterator(w.folder.path() / "cache")) {
        const fs::path inputs = entry.path() / "inputs";
        write(inputs, read_text(inputs) + " ");
    }
    CHECK_FALSE(w.cache().take(w.source, w.objects / "taken.o"));
}

TEST_CASE("a cache that cannot be used costs a compile and nothing else", "[grader]") {
    Work w;
    // An object with no list of what its compile read is not kept.
    const fs::path compiled = w.compile("first");
    fs::remove(fs::path(compiled).replace_extension(".d"));
    w.cache().keep(w.source, compiled);
    CHECK_FALSE(w.cache().take(w.source, w.objects / "taken.o"));
    std::size_t entries = 0;
    for ([[maybe_unused]] const fs::directory_entry& entry :
         fs::directory_iterator(w.folder.path() / "cache"))
        ++entries;
    CHECK(entries == 0);
}

TEST_CASE("an object compiled with the precompiled header is taken again until it is rebuilt",
          "[grader]") {
    Work w;
    w.precompile_header();
    w.cache().keep(w.source, w.compile("first"));
    CHECK(w.cache().take(w.source, w.objects / "taken.o"));
    // The build's header made again: its time moves, and every object compiled with it is stale.
    const fs::path built = w.toolchain.precompiled_header.string() + ".gch";
    fs::last_write_time(built, fs::last_write_time(built) + std::chrono::seconds(1));
    CHECK_FALSE(w.cache().take(w.source, w.objects / "stale.o"));
}
