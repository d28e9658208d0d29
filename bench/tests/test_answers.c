/* test_answers.c (bench, chapter 1): the answers' frames, from the probe's end to the judge's.
 *
 * Frames written with a run's secret are read back whole; a frame whose secret differs
 * from the run's in any one of its bytes (its checksum right: the forger computes it) is
 * refused, as is one for another exercise or out of order; the probe's secret is read
 * from its descriptor whole, or not at all. answers.c is compiled into this test (it is
 * the grader's, not the library's).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "exercise/answers.c"

#include <fcntl.h>

static const unsigned char run_secret[ANSWERS_SECRET] = {0x3a, 0x91, 0x07, 0xc4, 0x5e, 0x22,
                                                         0xf0, 0x19, 0x8b, 0x66, 0xd3, 0x40,
                                                         0x7f, 0xa8, 0x0c, 0xe5};

/* The bytes of a stream of `count` values 0.5, 1.5, ... for exercise `id` under `secret`,
 * into bytes[size]; returns how many. */
static size_t stream(const unsigned char secret[ANSWERS_SECRET], const char *id, int count,
                     unsigned char *bytes, size_t size)
{
    int ends[2];
    assert_int_equal(pipe(ends), 0);
    static AnswerWriter writer;
    answer_writer_init(&writer, ends[1], secret, id);
    for (int i = 0; i < count; i++)
        assert_int_equal(answer_put(&writer, 0.5 + i), 0);
    assert_int_equal(answer_end(&writer), 0);
    close(ends[1]);
    size_t got = 0;
    ssize_t n;
    while ((n = read(ends[0], bytes + got, size - got)) > 0)
        got += (size_t)n;
    close(ends[0]);
    return got;
}

static void test_a_stream_read_back(void **state)
{
    (void)state;
    static unsigned char bytes[1 << 16];
    size_t size = stream(run_secret, "2.1", 5, bytes, sizeof bytes);
    AnswerReader reader;
    answer_reader_init(&reader, run_secret, "2.1");
    /* a byte at a time: frames split anywhere are put together */
    int status = 0;
    for (size_t i = 0; i < size && status == 0; i++)
        status = answer_feed(&reader, bytes + i, 1);
    assert_int_equal(status, 1);
    assert_int_equal(reader.count, 5);
    assert_true(reader.values[4] == 4.5);
    answer_reader_free(&reader);
}

/* A forger who knows all of the secret but one byte: refused, whichever byte it is. */
static void test_every_byte_of_the_secret_counts(void **state)
{
    (void)state;
    static unsigned char bytes[1 << 16];
    int refused = 0;
    for (int at = 0; at < ANSWERS_SECRET; at++) {
        unsigned char guessed[ANSWERS_SECRET];
        memcpy(guessed, run_secret, ANSWERS_SECRET);
        guessed[at] ^= 0x01;
        size_t size = stream(guessed, "2.1", 3, bytes, sizeof bytes);
        AnswerReader reader;
        answer_reader_init(&reader, run_secret, "2.1");
        int status = answer_feed(&reader, bytes, size);
        if (status == -1 && strstr(reader.garbled, "does not carry this run's secret") &&
            reader.count == 0)
            refused++;
        else
            printf("a secret wrong in byte %d: status %d, %ld values taken (%s)\n", at, status,
                   reader.count, reader.garbled);
        answer_reader_free(&reader);
    }
    assert_int_equal(refused, ANSWERS_SECRET);
}

static void test_another_exercise_or_order_refused(void **state)
{
    (void)state;
    static unsigned char bytes[1 << 16];
    size_t size = stream(run_secret, "2.2", 3, bytes, sizeof bytes);
    AnswerReader reader;
    answer_reader_init(&reader, run_secret, "2.1");
    assert_int_equal(answer_feed(&reader, bytes, size), -1);
    assert_non_null(strstr(reader.garbled, "answers another exercise"));
    answer_reader_free(&reader);

    /* the first frame (3 values), then the whole stream again: frame 0 where 1 is due */
    size = stream(run_secret, "2.1", 3, bytes, sizeof bytes);
    answer_reader_init(&reader, run_secret, "2.1");
    assert_int_equal(answer_feed(&reader, bytes, ANSWERS_HEADER + 8 * 3 + 8), 0);
    assert_int_equal(reader.count, 3);
    assert_int_equal(answer_feed(&reader, bytes, size), -1);
    assert_non_null(strstr(reader.garbled, "out of order"));
    answer_reader_free(&reader);
}

static void test_the_secret_read_whole_or_not_at_all(void **state)
{
    (void)state;
    unsigned char secret[ANSWERS_SECRET];
    for (int bytes = ANSWERS_SECRET - 1; bytes <= ANSWERS_SECRET; bytes++) {
        int ends[2];
        assert_int_equal(pipe(ends), 0);
        assert_int_equal(answers_write_all(ends[1], run_secret, (size_t)bytes), 0);
        close(ends[1]);
        int status = answers_read_secret(ends[0], secret);
        assert_int_equal(status, bytes == ANSWERS_SECRET ? 0 : -1);
        assert_int_equal(fcntl(ends[0], F_GETFD), -1); /* closed, either way */
    }
    assert_memory_equal(secret, run_secret, ANSWERS_SECRET);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_stream_read_back),
        cmocka_unit_test(test_every_byte_of_the_secret_counts),
        cmocka_unit_test(test_another_exercise_or_order_refused),
        cmocka_unit_test(test_the_secret_read_whole_or_not_at_all),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
