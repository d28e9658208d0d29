/* answers.c (bench, chapter 1): framing, sending and checking a student's answers. See
 * answers.h.
 *
 * A frame, in the machine's own byte order (both ends run on it):
 *     "MCAN", kind (1: values, 2: end), sequence, count (u32 each), values sent before
 *     it (u64; the end frame: in all), the secret, the exercise's id, count doubles,
 *     then the FNV-1a checksum (u64) of everything before it.
 */
#include "answers.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAGIC "MCAN"
#define KIND_VALUES 1u
#define KIND_END 2u
#define HEADER ANSWERS_HEADER
#define CHECKSUM 8

typedef struct {
    uint32_t kind, sequence, count;
    uint64_t before;
    unsigned char secret[ANSWERS_SECRET];
    char id[ANSWERS_ID];
} Header;

static uint64_t checksum(const unsigned char *bytes, size_t size)
{
    uint64_t hash = 14695981039346656037u;
    for (size_t i = 0; i < size; i++)
        hash = (hash ^ bytes[i]) * 1099511628211u;
    return hash;
}

static void put_header(unsigned char *frame, const Header *h)
{
    memcpy(frame, MAGIC, 4);
    memcpy(frame + 4, &h->kind, 4);
    memcpy(frame + 8, &h->sequence, 4);
    memcpy(frame + 12, &h->count, 4);
    memcpy(frame + 16, &h->before, 8);
    memcpy(frame + 24, h->secret, ANSWERS_SECRET);
    memcpy(frame + 24 + ANSWERS_SECRET, h->id, ANSWERS_ID);
}

static void get_header(const unsigned char *frame, Header *h)
{
    memcpy(&h->kind, frame + 4, 4);
    memcpy(&h->sequence, frame + 8, 4);
    memcpy(&h->count, frame + 12, 4);
    memcpy(&h->before, frame + 16, 8);
    memcpy(h->secret, frame + 24, ANSWERS_SECRET);
    memcpy(h->id, frame + 24 + ANSWERS_SECRET, ANSWERS_ID);
}

int answers_write_all(int fd, const void *bytes, size_t size)
{
    const unsigned char *next = bytes;
    while (size > 0) {
        ssize_t n = write(fd, next, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return -1;
        next += n;
        size -= (size_t)n;
    }
    return 0;
}

int answers_new_secret(unsigned char secret[ANSWERS_SECRET])
{
    FILE *random = fopen("/dev/urandom", "rb");
    if (!random)
        return -1;
    size_t got = fread(secret, 1, ANSWERS_SECRET, random);
    fclose(random);
    if (got != ANSWERS_SECRET) {
        errno = EIO;
        return -1;
    }
    return 0;
}

int answers_read_secret(int fd, unsigned char secret[ANSWERS_SECRET])
{
    size_t got = 0;
    while (got < ANSWERS_SECRET) {
        ssize_t n = read(fd, secret + got, ANSWERS_SECRET - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    close(fd);
    if (got != ANSWERS_SECRET) {
        errno = EIO;
        return -1;
    }
    return 0;
}

/* ---- the probe's end ---- */

void answer_writer_init(AnswerWriter *w, int fd, const unsigned char secret[ANSWERS_SECRET],
                        const char *id)
{
    memset(w, 0, sizeof *w);
    w->fd = fd;
    memcpy(w->secret, secret, ANSWERS_SECRET);
    strncpy(w->id, id, ANSWERS_ID - 1);
}

static int send_frame(AnswerWriter *w, uint32_t kind)
{
    uint32_t count = kind == KIND_VALUES ? (uint32_t)w->buffered : 0;
    Header h = {kind, w->sequence++, count, w->sent, {0}, {0}};
    memcpy(h.secret, w->secret, ANSWERS_SECRET);
    memcpy(h.id, w->id, ANSWERS_ID);
    put_header(w->frame, &h);
    size_t size = HEADER + 8 * (size_t)count;
    uint64_t sum = checksum(w->frame, size);
    memcpy(w->frame + size, &sum, CHECKSUM);
    w->sent += count;
    w->buffered = 0;
    return answers_write_all(w->fd, w->frame, size + CHECKSUM);
}

int answer_put(AnswerWriter *w, double value)
{
    memcpy(w->frame + HEADER + 8 * (size_t)w->buffered++, &value, 8);
    return w->buffered == ANSWERS_FRAME ? send_frame(w, KIND_VALUES) : 0;
}

int answer_end(AnswerWriter *w)
{
    if (w->buffered > 0 && send_frame(w, KIND_VALUES) != 0)
        return -1;
    return send_frame(w, KIND_END);
}

/* ---- the judge's end ---- */

void answer_reader_init(AnswerReader *r, const unsigned char secret[ANSWERS_SECRET],
                        const char *id)
{
    memset(r, 0, sizeof *r);
    memcpy(r->secret, secret, ANSWERS_SECRET);
    strncpy(r->id, id, ANSWERS_ID - 1);
}

void answer_reader_free(AnswerReader *r)
{
    free(r->pending);
    free(r->values);
    r->pending = NULL;
    r->values = NULL;
}

/* `block`, or a larger copy of it, with room for `needed` items of `item` bytes (its
 * capacity doubled until enough); NULL when memory runs out (block is then untouched). */
static void *room_for(void *block, size_t *capacity, size_t needed, size_t item)
{
    if (needed <= *capacity)
        return block;
    size_t larger = *capacity ? *capacity : 1024;
    while (larger < needed)
        larger *= 2;
    void *bigger = realloc(block, larger * item);
    if (bigger)
        *capacity = larger;
    return bigger;
}

static int garbled(AnswerReader *r, const char *what)
{
    snprintf(r->garbled, sizeof r->garbled, "frame %u %s", (unsigned)r->sequence, what);
    return -1;
}

/* What is wrong with a header, or NULL. */
static const char *bad_header(const AnswerReader *r, const unsigned char *frame,
                              const Header *h)
{
    if (memcmp(frame, MAGIC, 4) != 0)
        return "is not a frame of the grader's";
    if (memcmp(h->secret, r->secret, ANSWERS_SECRET) != 0)
        return "does not carry this run's secret";
    if (memcmp(h->id, r->id, ANSWERS_ID) != 0)
        return "answers another exercise";
    if (h->kind != KIND_VALUES && h->kind != KIND_END)
        return "is of no known kind";
    if (h->sequence != r->sequence)
        return "is out of order";
    if (h->kind == KIND_VALUES && (h->count == 0 || h->count > ANSWERS_FRAME))
        return "holds an impossible number of values";
    if (h->kind == KIND_END && h->count != 0)
        return "is an end frame with values";
    if (h->before != (uint64_t)r->count)
        return "disagrees with the number of values before it";
    if (r->count + (long)h->count > ANSWERS_MAX)
        return "brings more values than any exercise asks for";
    return NULL;
}

/* Take one whole frame from the front of r->pending: 1 when one was taken, 0 when it is
 * not all there yet, -1 when garbled, -2 out of memory. */
static int take_frame(AnswerReader *r)
{
    if (r->pending_size < HEADER)
        return 0;
    Header h;
    get_header(r->pending, &h);
    const char *bad = bad_header(r, r->pending, &h);
    if (bad)
        return garbled(r, bad);
    size_t size = HEADER + 8 * (size_t)h.count + CHECKSUM;
    if (r->pending_size < size)
        return 0;
    uint64_t sum;
    memcpy(&sum, r->pending + size - CHECKSUM, CHECKSUM);
    if (sum != checksum(r->pending, size - CHECKSUM))
        return garbled(r, "is damaged: its checksum does not match");
    if (h.count > 0) {
        double *values =
            room_for(r->values, &r->capacity, (size_t)r->count + h.count, sizeof *values);
        if (!values)
            return -2;
        r->values = values;
        memcpy(r->values + r->count, r->pending + HEADER, 8 * (size_t)h.count);
        r->count += h.count;
    }
    r->sequence++;
    r->ended = h.kind == KIND_END;
    memmove(r->pending, r->pending + size, r->pending_size - size);
    r->pending_size -= size;
    return 1;
}

int answer_feed(AnswerReader *r, const unsigned char *bytes, size_t size)
{
    if (r->garbled[0])
        return -1;
    if (r->ended)
        return 1;
    unsigned char *pending =
        room_for(r->pending, &r->pending_capacity, r->pending_size + size, 1);
    if (!pending)
        return -2;
    r->pending = pending;
    memcpy(r->pending + r->pending_size, bytes, size);
    r->pending_size += size;
    int taken;
    while (!r->ended && (taken = take_frame(r)) == 1)
        ;
    if (r->ended)
        return 1;
    return taken;
}
