// Shared by the fuzz targets: their checks, and the input as a file.
#ifndef CT_FUZZ_FUZZ_H
#define CT_FUZZ_FUZZ_H

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

// A check beyond the sanitizers: its failure aborts, and libFuzzer keeps the
// input.
#define CHECK(cond)                                                                   \
    do {                                                                              \
        if (!(cond)) {                                                                \
            std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__,     \
                         #cond);                                                      \
            std::abort();                                                             \
        }                                                                             \
    } while (0)

// The fuzz input as a file the readers can open by name: an anonymous
// in-memory file (memfd), named through /proc/self/fd.
class MemFile {
public:
    MemFile(const uint8_t *data, size_t size)
    {
        fd_ = memfd_create("ct-fuzz", 0);
        if (fd_ < 0) {
            std::perror("memfd_create");
            std::abort();
        }
        for (size_t done = 0; done < size;) {
            const ssize_t n = write(fd_, data + done, size - done);
            if (n <= 0) {
                std::perror("write");
                std::abort();
            }
            done += (size_t)n;
        }
        std::snprintf(path_, sizeof path_, "/proc/self/fd/%d", fd_);
    }
    ~MemFile() { close(fd_); }
    const char *path() const { return path_; }

private:
    int fd_;
    char path_[64];
};

#endif
