#include "app/view/view_session.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"

using namespace raystep;
namespace fs = std::filesystem;

TEST_CASE(
    "ViewSession::scene_list: the scenes under scenes/, not links out of it, not names "
    "that are not UTF-8",
    "[app]") {
    const testing::ScratchFolder folder("view-session");
    const fs::path project = folder.path() / "project";
    fs::create_directories(project / "scenes" / "stage2");
    std::ofstream(project / "scenes" / "stage2" / "own.test")
        << "size 4 4\ncamera 0 0 4 0 0 0 0 1 0 45\n";
    std::ofstream(project / "scenes" / "notes.txt") << "not a scene\n";
    // A link to a file outside: opening it would show its first line in the load error.
    std::ofstream(folder.path() / "secret.test") << "a secret line\n";
    fs::create_symlink(folder.path() / "secret.test", project / "scenes" / "link.test");
    // A link to a scene inside is the project's own.
    fs::create_symlink("stage2/own.test", project / "scenes" / "alias.test");
    // A name the page could not send back: JSON carries UTF-8 only.
    std::ofstream(project / "scenes" / "bad\xff.test") << "size 4 4\n";

    ViewSession session(project, 1);
    CHECK(session.scene_list() == std::vector<std::string>{"alias.test", "stage2/own.test"});
    CHECK_THROWS_AS(session.open_listed("link.test"), std::invalid_argument);
    CHECK_THROWS_AS(session.open_listed("../secret.test"), std::invalid_argument);
    session.open_listed("stage2/own.test");
    CHECK(session.load_error() == "");
    CHECK(session.scene());
}
