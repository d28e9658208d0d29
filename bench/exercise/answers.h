/* answers.h (bench, chapter 1): the channel that carries a student's answers to the grader.
 *
 * The student's program (the probe) computes raw values with the student's functions and
 * writes them in frames to a pipe of its own; the grader (the judge, built from the
 * solution) reads them back. Each frame carries the run's secret, the exercise, its
 * sequence number, the values sent before it, up to ANSWERS_FRAME values and a
 * checksum; an end frame gives the total. A frame that breaks any of these rules makes
 * the rest of the stream garbled: the judge keeps the values before it, and no more.
 */
#ifndef ANSWERS_H
#define ANSWERS_H

#include <stddef.h>
#include <stdint.h>

#define ANSWERS_FRAME 4096     /* values per frame at most */
#define ANSWERS_MAX (1L << 24) /* values per run at most */
#define ANSWERS_SECRET 16      /* bytes of a run's secret */
#define ANSWERS_SECRET_FD 4    /* where the probe reads it, once, at its start */
#define ANSWERS_ID 16          /* bytes of an exercise's id in a frame */
#define ANSWERS_HEADER (24 + ANSWERS_SECRET + ANSWERS_ID) /* bytes before a frame's values */

/* The probe's end: values are buffered and sent a frame at a time. */
typedef struct {
    int fd;
    unsigned char secret[ANSWERS_SECRET];
    char id[ANSWERS_ID];
    uint32_t sequence;
    uint64_t sent; /* values in the frames already written */
    int buffered;  /* values in the frame being filled */
    unsigned char frame[ANSWERS_HEADER + 8 * ANSWERS_FRAME + 8];
} AnswerWriter;

/* The judge's end: the values of the whole frames received so far. */
typedef struct {
    unsigned char secret[ANSWERS_SECRET];
    char id[ANSWERS_ID];
    uint32_t sequence;
    unsigned char *pending; /* bytes of a frame not yet complete */
    size_t pending_size, pending_capacity;
    double *values;
    long count;
    size_t capacity;   /* values that fit in `values` */
    int ended;         /* the end frame arrived */
    char garbled[256]; /* what was wrong with the first bad frame, or "" */
} AnswerReader;

/* Write all `size` bytes to fd, again after an interrupting signal. Returns 0, or -1
 * with errno set. */
int answers_write_all(int fd, const void *bytes, size_t size);

/* A fresh secret from /dev/urandom. Returns 0, or -1 with errno set. */
int answers_new_secret(unsigned char secret[ANSWERS_SECRET]);

/* The probe: the secret, read from fd (the judge's pipe, closed then). Returns 0, or -1
 * with errno set when fewer than ANSWERS_SECRET bytes were there. */
int answers_read_secret(int fd, unsigned char secret[ANSWERS_SECRET]);

/* The probe: open the stream for exercise `id` on `fd`; add a value; end the stream.
 * answer_put and answer_end return 0, or -1 with errno set when the pipe fails. */
void answer_writer_init(AnswerWriter *w, int fd, const unsigned char secret[ANSWERS_SECRET],
                        const char *id);
int answer_put(AnswerWriter *w, double value);
int answer_end(AnswerWriter *w);

/* The judge: expect exercise `id` with `secret`; feed it the bytes read from the pipe.
 * answer_feed returns 1 once the end frame is in, -1 once the stream is garbled (the
 * reason in r->garbled; later bytes are ignored), 0 while more is to come, and -2 when
 * memory runs out. */
void answer_reader_init(AnswerReader *r, const unsigned char secret[ANSWERS_SECRET],
                        const char *id);
int answer_feed(AnswerReader *r, const unsigned char *bytes, size_t size);
void answer_reader_free(AnswerReader *r);

#endif
