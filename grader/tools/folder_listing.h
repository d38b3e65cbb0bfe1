#pragma once

#include <set>
#include <string>

namespace raystep::grade {

/// What list_folder may take: files named in `wanted`, each of at most `largest_file` bytes, and
/// `total` bytes in all.
struct FolderTake {
    std::string into;  ///< the folder the contents go to, as <into>/N, N the entry's number
    long long largest_file = 0;
    long long total = 0;
    std::set<std::string> wanted;
};

/// Lists the folder open at descriptor `root`, as raystep-unpack lists an archive
/// (unpacked_entry.h), breadth first, past the folders that tools make (.git, build,
/// node_modules...), and copies out the regular files that `take` asks for. Every entry is opened
/// from its parent's descriptor by its own name with O_NOFOLLOW, never by a path: a symbolic link
/// at any depth is listed as a link and never followed, so nothing outside the folder is ever read.
/// A file with more than one name (a hard link) is listed as a link too, since its other name may
/// lie anywhere. Returns 0 when it read the whole folder, 4 when it stopped early (too many
/// entries, too deep, a folder it could not read), having said why on stderr.
int list_folder(int root, const FolderTake& take);

}  // namespace raystep::grade
