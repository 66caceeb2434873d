#define _POSIX_C_SOURCE 200809L
#include "video.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#define Y4M_SIGNATURE "YUV4MPEG2 "
/* The bytes read before deciding what the input is: Y4M's signature, or a
 * container's magic (an AVI's is at bytes 8-11). */
#define SNIFF_BYTES 12
#define Y4M_MAX_LINE 1024
#define MAX_SIDE 16384

struct video_input {
    FILE *f;
    int owns_file;
    int y4m;
    int width, height;
    uint32_t format;
    size_t frame_bytes;
    uint8_t *buf;
    /* Bytes already read past the signature check, replayed first. */
    unsigned char pending[16];
    size_t pending_len, pending_pos;
    long long frame_index;
    long header_bytes; /* Y4M: the header line's */
    /* video_keep() and video_replay(): the first frames read, kept (up to
     * keep_max), and how many of them were replayed. */
    uint8_t *kept;
    long long keep_max, kept_n, replayed;
    int replaying;
    /* A failed read fails every read after it (after the kept frames, when
     * replaying), with its message. */
    int failed;
    char error[256];
};

size_t frame_bytes(uint32_t format, int width, int height)
{
    if (width < 1 || height < 1 || width > MAX_SIDE || height > MAX_SIDE)
        return 0;
    size_t luma = (size_t)width * (size_t)height;
    size_t chroma = (size_t)((width + 1) / 2) * (size_t)((height + 1) / 2);
    switch (format) {
    case CT_FORMAT_GRAY8: return luma;
    case CT_FORMAT_I420:
    case CT_FORMAT_NV12: return luma + 2 * chroma;
    default: return 0;
    }
}

/* Reads up to n bytes, first from the replay buffer; returns bytes read. */
static size_t read_bytes(video_input *in, void *dst, size_t n)
{
    size_t got = 0;
    unsigned char *d = dst;
    while (got < n && in->pending_pos < in->pending_len)
        d[got++] = in->pending[in->pending_pos++];
    if (got < n)
        got += fread(d + got, 1, n - got, in->f);
    return got;
}

/* Reads one line (without '\n') of at most max bytes. Returns its length, -1
 * at end of file before any byte, -2 when too long or cut by end of file. */
static long read_line(video_input *in, char *line, size_t max)
{
    size_t n = 0;
    for (;;) {
        unsigned char c;
        if (read_bytes(in, &c, 1) != 1)
            return n == 0 ? -1 : -2;
        if (c == '\n')
            break;
        if (n + 1 >= max)
            return -2;
        line[n++] = (char)c;
    }
    line[n] = '\0';
    return (long)n;
}

/* The container the first bytes of a file announce, or NULL: files ffmpeg
 * decodes that are neither raw video nor Y4M. */
static const char *container_of(const unsigned char *b, size_t n)
{
    static const struct {
        size_t at, len;
        const char *magic, *name;
    } kinds[] = {
        {4, 4, "ftyp", "an MP4 or QuickTime (MOV)"},
        {8, 4, "AVI ", "an AVI"},
        {0, 4, "\x1a\x45\xdf\xa3", "a Matroska or WebM"},
        {0, 4, "OggS", "an Ogg"},
        {0, 3, "FLV", "a Flash (FLV)"},
        {0, 4, "\x30\x26\xb2\x75", "an ASF or WMV"},
        {0, 4, "\x00\x00\x01\xba", "an MPEG program stream"},
        {0, 4, "\x89PNG", "a PNG"},
        {0, 3, "\xff\xd8\xff", "a JPEG"},
        {0, 4, "GIF8", "a GIF"},
    };
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++)
        if (n >= kinds[i].at + kinds[i].len &&
            !memcmp(b + kinds[i].at, kinds[i].magic, kinds[i].len))
            return kinds[i].name;
    return NULL;
}

/* Whether a file's name ends as an encoded video's does (a transport
 * stream, an elementary stream: no magic in their first bytes). */
static int video_extension(const char *path)
{
    static const char *const ext[] = {".ts", ".mts", ".m2ts", ".mpg", ".mpeg", ".h264",
                                      ".h265", ".hevc", ".264", ".265", ".mjpeg", ".mxf",
                                      ".3gp", ".mp4", ".mov", ".mkv", ".webm", ".avi",
                                      ".m4v", ".ogv", ".flv", ".wmv"};
    const char *dot = strrchr(path, '.');
    if (!dot || strchr(dot, '/'))
        return 0;
    for (size_t i = 0; i < sizeof ext / sizeof ext[0]; i++)
        if (!strcasecmp(dot, ext[i]))
            return 1;
    return 0;
}

/* A decimal number in [lo, hi] that fills the whole of s, or -1. */
static long parse_number(const char *s, long lo, long hi)
{
    if (*s < '0' || *s > '9') /* strtol would take a sign or blanks */
        return -1;
    char *end;
    errno = 0;
    const long v = strtol(s, &end, 10);
    return *end || errno || v < lo || v > hi ? -1 : v;
}

static int parse_y4m_header(video_input *in, video_info *info, char *err, size_t err_len)
{
    char line[Y4M_MAX_LINE];
    long len = read_line(in, line, sizeof line);
    if (len < 0) {
        snprintf(err, err_len, "bad Y4M header: %s", len == -1 ? "empty" : "too long or cut");
        return -1;
    }
    if ((size_t)len != strlen(line)) {
        snprintf(err, err_len, "bad Y4M header: a NUL byte in it");
        return -1;
    }
    long w = 0, h = 0, rn = 0, rd = 0;
    uint32_t format = CT_FORMAT_I420; /* 4:2:0 is Y4M's default */
    char *save = NULL;
    char *tok = strtok_r(line + strlen(Y4M_SIGNATURE) - 1, " ", &save);
    for (; tok; tok = strtok_r(NULL, " ", &save)) {
        switch (tok[0]) {
        case 'W':
            w = parse_number(tok + 1, 1, MAX_SIDE);
            break;
        case 'H':
            h = parse_number(tok + 1, 1, MAX_SIDE);
            break;
        case 'F': {
            char *colon = strchr(tok + 1, ':');
            if (colon) {
                *colon = '\0';
                rn = parse_number(tok + 1, 1, INT_MAX);
                rd = parse_number(colon + 1, 1, INT_MAX);
                *colon = ':';
            }
            /* The rate as ct-track's --fps takes it. */
            if (!colon || rn < 0 || rd < 0 || (double)rn / rd < VIDEO_MIN_RATE ||
                (double)rn / rd > VIDEO_MAX_RATE) {
                snprintf(err, err_len,
                         "bad Y4M header: frame rate '%s' is not NUM:DEN of %g to %g "
                         "frames/s",
                         tok, VIDEO_MIN_RATE, VIDEO_MAX_RATE);
                return -1;
            }
            break;
        }
        case 'C':
            if (!strcmp(tok, "C420") || !strcmp(tok, "C420jpeg") ||
                !strcmp(tok, "C420paldv") || !strcmp(tok, "C420mpeg2")) {
                format = CT_FORMAT_I420;
            } else if (!strcmp(tok, "Cmono")) {
                format = CT_FORMAT_GRAY8;
            } else {
                snprintf(err, err_len,
                         "unsupported Y4M colour space '%s': ct-track reads 4:2:0 "
                         "(C420, C420jpeg, C420paldv, C420mpeg2) and Cmono; convert with "
                         "ffmpeg -pix_fmt yuv420p",
                         tok + 1);
                return -1;
            }
            break;
        case 'I':
        case 'A':
        case 'X':
            break; /* interlacing, aspect and extensions do not matter here */
        default:
            snprintf(err, err_len, "bad Y4M header: unknown field '%s'", tok);
            return -1;
        }
    }
    if (w < 1 || h < 1) {
        snprintf(err, err_len,
                 "bad Y4M header: size %s is missing or absurd (each side must be in [1, %d])",
                 w < 1 ? "W" : "H", MAX_SIDE);
        return -1;
    }
    in->width = (int)w;
    in->height = (int)h;
    in->format = format;
    info->rate_num = (int)rn;
    info->rate_den = (int)rd;
    info->frames = -1;
    in->header_bytes = len + 1;
    return 0;
}

/* The whole frames of a Y4M file of `size` bytes whose frames start at
 * `pos`: each a FRAME line (with parameters or not) and frame_bytes of
 * pixels. Read with pread(), so that the stream's position is kept. */
static long long count_y4m_frames(int fd, long long pos, long long size, size_t frame_bytes)
{
    long long n = 0;
    char line[Y4M_MAX_LINE];
    while (pos < size) {
        const ssize_t got = pread(fd, line, sizeof line, (off_t)pos);
        const char *nl = got > 0 ? memchr(line, '\n', (size_t)got) : NULL;
        if (!nl || strncmp(line, "FRAME", 5) != 0)
            break;
        pos += (nl - line) + 1 + (long long)frame_bytes;
        if (pos > size)
            break;
        n++;
    }
    return n;
}

/* A regular file's frames into *frames (else it stays as it is). Returns
 * 0, or -1 with a message when a raw file is no whole number of frames. */
static int count_frames(const video_input *in, const char *path, long long *frames, char *err,
                        size_t err_len)
{
    struct stat st;
    if (fstat(fileno(in->f), &st) != 0 || !S_ISREG(st.st_mode))
        return 0;
    const long long total = (long long)st.st_size;
    if (in->y4m) {
        *frames = count_y4m_frames(fileno(in->f), in->header_bytes, total, in->frame_bytes);
        return 0;
    }
    if (total % (long long)in->frame_bytes != 0) {
        snprintf(err, err_len,
                 "'%s' has %lld bytes, not a whole number of %dx%d frames of %zu "
                 "bytes: check --size and --format",
                 path, total, in->width, in->height, in->frame_bytes);
        return -1;
    }
    *frames = total / (long long)in->frame_bytes;
    return 0;
}

int video_open(const char *path, const video_params *params, video_input **out,
                  video_info *info, char *err, size_t err_len)
{
    *out = NULL;
    memset(info, 0, sizeof *info);
    video_input *in = calloc(1, sizeof *in);
    if (!in) {
        snprintf(err, err_len, "out of memory");
        return -1;
    }
    int is_stdin = !strcmp(path, "-");
    if (is_stdin) {
        in->f = stdin;
    } else {
        in->f = fopen(path, "rb");
        if (!in->f) {
            snprintf(err, err_len, "cannot open '%s': %s", path, strerror(errno));
            free(in);
            return -1;
        }
        in->owns_file = 1;
        struct stat st;
        if (fstat(fileno(in->f), &st) == 0 && S_ISDIR(st.st_mode)) {
            snprintf(err, err_len, "cannot read '%s': it is a directory", path);
            video_close(in);
            return -1;
        }
    }

    in->pending_len = fread(in->pending, 1, SNIFF_BYTES, in->f);
    if (ferror(in->f)) {
        snprintf(err, err_len, "cannot read '%s': %s", path, strerror(errno));
        video_close(in);
        return -1;
    }
    in->y4m = in->pending_len >= strlen(Y4M_SIGNATURE) &&
              !memcmp(in->pending, Y4M_SIGNATURE, strlen(Y4M_SIGNATURE));
    if (in->y4m) {
        /* Keep the space so the tokenizer sees " W640 ..." after it. */
        in->pending_pos = 0;
        if (parse_y4m_header(in, info, err, err_len) < 0) {
            video_close(in);
            return -1;
        }
    } else {
        const char *container = container_of(in->pending, in->pending_len);
        if (!container && !is_stdin && (params->width <= 0 || params->height <= 0) &&
            video_extension(path))
            container = "an encoded video";
        if (container) {
            const char *name = is_stdin ? "FILE" : path;
            snprintf(err, err_len,
                     "%s%s%s holds %s file, which ct-track does not decode (it reads Y4M "
                     "and raw video): pipe it through ffmpeg as Y4M, e.g.\n"
                     "  ffmpeg -i '%s' -f yuv4mpegpipe -pix_fmt yuv420p - | ct-track [OPTIONS] -",
                     is_stdin ? "" : "'", is_stdin ? "standard input" : path,
                     is_stdin ? "" : "'", container, name);
            video_close(in);
            return -1;
        }
        if (params->width <= 0 || params->height <= 0) {
            snprintf(err, err_len,
                     "'%s' is not Y4M: give the raw video's size with --size WxH", path);
            video_close(in);
            return -1;
        }
        in->width = params->width;
        in->height = params->height;
        in->format = params->format;
        info->frames = -1;
    }
    in->frame_bytes = frame_bytes(in->format, in->width, in->height);
    if (in->frame_bytes == 0) {
        snprintf(err, err_len, "size %dx%d is absurd (each side must be in [1, %d])",
                 in->width, in->height, MAX_SIDE);
        video_close(in);
        return -1;
    }
    if (!is_stdin && count_frames(in, path, &info->frames, err, err_len) < 0) {
        video_close(in);
        return -1;
    }
    in->buf = malloc(in->frame_bytes);
    if (!in->buf) {
        snprintf(err, err_len, "out of memory for a %dx%d frame", in->width, in->height);
        video_close(in);
        return -1;
    }
    info->width = in->width;
    info->height = in->height;
    info->format = in->format;
    *out = in;
    return 0;
}

/* The frame in buf as a ct_frame. */
static void describe(const video_input *in, const uint8_t *buf, ct_frame *frame)
{
    ct_frame_default(frame, sizeof *frame);
    frame->format = in->format;
    frame->width = in->width;
    frame->height = in->height;
    const int cw = (in->width + 1) / 2, ch = (in->height + 1) / 2;
    const size_t luma = (size_t)in->width * (size_t)in->height;
    frame->planes[0] = buf;
    frame->strides[0] = in->width;
    if (in->format == CT_FORMAT_I420) {
        frame->planes[1] = buf + luma;
        frame->planes[2] = buf + luma + (size_t)cw * ch;
        frame->strides[1] = frame->strides[2] = cw;
    } else if (in->format == CT_FORMAT_NV12) {
        frame->planes[1] = buf + luma;
        frame->strides[1] = 2 * cw;
    }
}

static int read_frame(video_input *in, ct_frame *frame, char *err, size_t err_len);

int video_keep(video_input *in, long long frames, char *err, size_t err_len)
{
    if (in->frame_index != 0 || in->kept || frames < 1) {
        snprintf(err, err_len, "frames can be kept only from the first, and once");
        return -1;
    }
    if ((unsigned long long)frames > SIZE_MAX / in->frame_bytes ||
        !(in->kept = malloc((size_t)frames * in->frame_bytes))) {
        snprintf(err, err_len, "cannot keep %lld frames of %zu bytes in memory", frames,
                 in->frame_bytes);
        return -1;
    }
    in->keep_max = frames;
    return 0;
}

int video_kept(video_input *in, long long i, ct_frame *frame)
{
    if (i < 0 || i >= in->kept_n)
        return 0;
    describe(in, in->kept + (size_t)i * in->frame_bytes, frame);
    return 1;
}

long long video_replay(video_input *in)
{
    in->replaying = 1;
    in->replayed = 0;
    return in->kept_n;
}

int video_read(video_input *in, ct_frame *frame, char *err, size_t err_len)
{
    if (in->replaying && in->replayed < in->kept_n) {
        describe(in, in->kept + (size_t)in->replayed++ * in->frame_bytes, frame);
        return 1;
    }
    if (in->failed) {
        snprintf(err, err_len, "%s", in->error);
        return -1;
    }
    const int got = read_frame(in, frame, err, err_len);
    if (got < 0) {
        in->failed = 1;
        snprintf(in->error, sizeof in->error, "%s", err);
    }
    return got;
}

/* The next frame from the input itself (video_read() without the replay and
 * the sticky error). */
static int read_frame(video_input *in, ct_frame *frame, char *err, size_t err_len)
{
    if (in->y4m) {
        char line[Y4M_MAX_LINE];
        long len = read_line(in, line, sizeof line);
        if (len == -1)
            return 0;
        if (len < 0 || (size_t)len != strlen(line) || strncmp(line, "FRAME", 5) != 0 ||
            (line[5] != '\0' && line[5] != ' ')) {
            snprintf(err, err_len, "bad Y4M frame header at frame %lld", in->frame_index + 1);
            return -1;
        }
    }
    size_t got = read_bytes(in, in->buf, in->frame_bytes);
    if (got == 0 && !in->y4m && !ferror(in->f))
        return 0;
    if (got < in->frame_bytes) {
        if (ferror(in->f))
            snprintf(err, err_len, "read error at frame %lld: %s", in->frame_index + 1,
                     strerror(errno));
        else
            snprintf(err, err_len,
                     "truncated frame %lld: %zu of %zu bytes (check --size and --format)",
                     in->frame_index + 1, got, in->frame_bytes);
        return -1;
    }
    in->frame_index++;
    if (!in->replaying && in->kept_n < in->keep_max) {
        uint8_t *copy = in->kept + (size_t)in->kept_n++ * in->frame_bytes;
        memcpy(copy, in->buf, in->frame_bytes);
    }
    describe(in, in->buf, frame);
    return 1;
}

void video_close(video_input *in)
{
    if (!in)
        return;
    if (in->owns_file && in->f)
        fclose(in->f);
    free(in->kept);
    free(in->buf);
    free(in);
}

static uint8_t clamp_byte(int v)
{
    return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
}

void i420_to_bgr24(const ct_frame *f, uint8_t *out)
{
    for (int y = 0; y < f->height; y++)
        for (int x = 0; x < f->width; x++) {
            const int c = f->planes[0][(size_t)y * f->strides[0] + x] - 16;
            const int d = f->planes[1][(size_t)(y / 2) * f->strides[1] + x / 2] - 128;
            const int e = f->planes[2][(size_t)(y / 2) * f->strides[2] + x / 2] - 128;
            *out++ = clamp_byte((298 * c + 516 * d + 128) / 256);
            *out++ = clamp_byte((298 * c - 100 * d - 208 * e + 128) / 256);
            *out++ = clamp_byte((298 * c + 409 * e + 128) / 256);
        }
}
