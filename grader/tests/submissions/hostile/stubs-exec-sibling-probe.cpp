// Hostile, every stage: the student stubs of stages/ and nothing else, plus this code appended to
// the first file of each stage's manifest. Its static constructor runs before the probe's main and
// tries to borrow the reference: it looks upwards from its own program's folder for another
// executable named like a probe (raystep-probe*, a sibling stageN, pipeline), in each folder and
// the folders in it, and execs it with its own stdin and stdout, so that the queries go to a
// program whose stages come from the reference. Failing that, it execs any other executable it
// finds there. The honest grade is 0: every stage is a stub. corpus_test.cpp assembles the
// submission and asserts it.

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

// Folders at the root that hold the system, not the grader: exec'ing what is there answers
// nothing.
bool system_folder(const std::string& path) {
    for (const char* folder : {"/bin", "/sbin", "/usr", "/lib", "/lib32", "/lib64", "/libx32",
                               "/etc", "/proc", "/sys", "/dev", "/boot", "/run", "/var"}) {
        if (path == folder) return true;
    }
    return false;
}

std::vector<std::string> entries_of(const std::string& folder) {
    std::vector<std::string> paths;
    if (DIR* dir = opendir(folder.c_str())) {
        while (const dirent* entry = readdir(dir)) {
            const std::string name = entry->d_name;
            if (name != "." && name != "..")
                paths.push_back((folder == "/" ? "" : folder) + "/" + name);
        }
        closedir(dir);
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

// 0: a program with every stage from the reference; 1: a sibling probe, every stage from the
// reference but its own (the latest stage first: the earlier stages, which a stage builds on,
// are then the reference's); 2: the pipeline; 3: anything else that runs.
int preference(const std::string& path) {
    const std::string name = path.substr(path.rfind('/') + 1);
    if (name.rfind("raystep-probe", 0) == 0) return 0;
    if (name.rfind("stage", 0) == 0) return 1;
    if (name == "pipeline") return 2;
    return 3;
}

struct BorrowTheReference {
    BorrowTheReference() {
        // A probe handed over to must answer, not hand over again.
        if (std::getenv("RAYSTEP_BORROWED")) return;
        setenv("RAYSTEP_BORROWED", "1", 1);
        struct stat self;
        char buffer[4096];
        const ssize_t length = readlink("/proc/self/exe", buffer, sizeof buffer - 1);
        if (stat("/proc/self/exe", &self) != 0 || length <= 0) return;
        std::string folder(buffer, static_cast<std::size_t>(length));

        std::vector<std::string> found[4];
        const auto consider = [&](const std::string& path) {
            struct stat file;
            if (stat(path.c_str(), &file) != 0 || !S_ISREG(file.st_mode)) return;
            if (file.st_dev == self.st_dev && file.st_ino == self.st_ino) return;
            if (access(path.c_str(), X_OK) == 0) found[preference(path)].push_back(path);
        };
        do {
            folder = folder.substr(0, folder.rfind('/'));
            const std::string here = folder.empty() ? "/" : folder;
            for (const std::string& path : entries_of(here)) {
                if (system_folder(path)) continue;
                consider(path);
                for (const std::string& inner : entries_of(path))
                    consider(inner);
            }
        } while (!folder.empty());

        std::reverse(found[1].begin(), found[1].end());
        for (const std::vector<std::string>& programs : found) {
            for (const std::string& program : programs) {
                char* argv[] = {const_cast<char*>(program.c_str()), nullptr};
                execv(program.c_str(), argv);  // returns only when it could not
            }
        }
    }
};

const BorrowTheReference borrow;

}  // namespace
