// raystep-unpack: lists a submission, an archive of any kind libarchive reads (zip, tar and its
// compressed forms, 7z, ...) or a folder, and copies out the few entries raystep-grade asks for,
// by file name. It is the grader's own code but reads a submission's bytes, so raystep-grade runs
// it in the sandbox, as an unprivileged user, with the submission on its stdin and only an empty
// folder in view (grader/grade/submission.cpp).
//
//   raystep-unpack FOLDER MAX_FILE_BYTES MAX_TOTAL_BYTES NAME... < SUBMISSION
//
// Writes one JSON line per entry on stdout (unpacked_entry.h): {"path", "kind" (file, folder,
// link, other), "size", "taken"}, and a link's "target"; an entry taken is a regular file whose
// last path component is one of the NAMEs, of at most MAX_FILE_BYTES, while the bytes taken stay
// within MAX_TOTAL_BYTES; its contents go to FOLDER/N, N its entry's number from 0. No entry's path
// ever reaches the file system, so no name (absolute, "..", a link's target, bytes that are not
// UTF-8) can place a file anywhere else. A folder on stdin is read through that descriptor alone,
// one name at a time, following no link (folder_listing.h). Exit codes: 0 read to the end; 3 not
// an archive it can read; 4 the archive broke partway, or the folder could not be read to its end
// (the lines before stand); 2 a bad command line. Whatever went wrong is said on stderr.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <archive.h>
#include <archive_entry.h>

#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "grader/grade/archive_entry_name.h"
#include "grader/tools/folder_listing.h"
#include "grader/tools/unpacked_entry.h"

namespace {

// A submission is a few dozen files: an archive of more entries than this is not one, and
// listing it would only cost time.
constexpr long kMostArchiveEntries = 100000;

std::string kind_of(archive_entry* entry) {
    if (archive_entry_hardlink(entry) != nullptr) return "link";
    switch (archive_entry_filetype(entry)) {
        case AE_IFREG:
            return "file";
        case AE_IFDIR:
            return "folder";
        case AE_IFLNK:
            return "link";
        default:
            return "other";
    }
}

// Copies the entry's data to `file`, at most `limit` bytes; false when it is longer or a read or
// write fails.
bool copy_data(archive* reader, const std::string& file, long long limit) {
    const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) return false;
    long long copied = 0;
    char buffer[65536];
    bool ok = true;
    for (;;) {
        const la_ssize_t got = archive_read_data(reader, buffer, sizeof buffer);
        if (got == 0) break;
        if (got < 0 || copied + got > limit ||
            write(fd, buffer, static_cast<std::size_t>(got)) != got) {
            ok = false;
            break;
        }
        copied += got;
    }
    ok = close(fd) == 0 && ok;
    if (!ok) unlink(file.c_str());
    return ok;
}

long long number_argument(const char* text) {
    char* end = nullptr;
    const long long value = std::strtoll(text, &end, 10);
    return *end == '\0' && value >= 0 ? value : -1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4 || number_argument(argv[2]) < 0 || number_argument(argv[3]) < 0) {
        std::fprintf(
            stderr,
            "usage: raystep-unpack FOLDER MAX_FILE_BYTES MAX_TOTAL_BYTES NAME... < SUBMISSION\n");
        return 2;
    }
    const std::string folder = argv[1];
    const long long max_file = number_argument(argv[2]);
    const long long max_total = number_argument(argv[3]);
    const std::set<std::string> wanted(argv + 4, argv + argc);

    struct stat submission {};
    if (fstat(STDIN_FILENO, &submission) == 0 && S_ISDIR(submission.st_mode)) {
        return raystep::grade::list_folder(STDIN_FILENO, {folder, max_file, max_total, wanted});
    }

    archive* reader = archive_read_new();
    archive_read_support_filter_all(reader);
    archive_read_support_format_all(reader);
    if (archive_read_open_fd(reader, STDIN_FILENO, 65536) != ARCHIVE_OK) {
        std::fprintf(stderr, "not an archive raystep-grade can read: %s\n",
                     archive_error_string(reader));
        archive_read_free(reader);
        return 3;
    }

    long long taken_bytes = 0;
    int status = 0;
    archive_entry* entry = nullptr;
    for (long index = 0;; ++index) {
        const int read = archive_read_next_header(reader, &entry);
        if (read == ARCHIVE_EOF) break;
        if (read < ARCHIVE_WARN || index >= kMostArchiveEntries) {
            std::fprintf(stderr, "the archive %s after %ld entries%s%s\n",
                         index >= kMostArchiveEntries ? "was cut" : "broke", index,
                         read < ARCHIVE_WARN ? ": " : "",
                         read < ARCHIVE_WARN ? archive_error_string(reader) : "");
            status = 4;
            break;
        }
        const char* raw_path = archive_entry_pathname(entry);
        const std::string path = raw_path ? raw_path : "";
        const std::string kind = kind_of(entry);
        const long long size = archive_entry_size_is_set(entry) ? archive_entry_size(entry) : -1;
        bool taken = false;
        if (kind == "file" && wanted.count(raystep::grade::archive_entry_name(path)) > 0 &&
            size >= 0 && size <= max_file && taken_bytes + size <= max_total) {
            taken = copy_data(reader, folder + "/" + std::to_string(index), max_file);
            if (taken) taken_bytes += size;
        }
        const char* target = archive_entry_symlink(entry);
        if (!target) target = archive_entry_hardlink(entry);
        raystep::grade::print_entry(path, kind, size, taken, target ? target : "");
    }
    archive_read_free(reader);
    return status;
}
