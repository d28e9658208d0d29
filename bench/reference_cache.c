/* reference_cache.c (bench, chapter 2): the reference cache and the program that fills it.
 * See reference_cache.h. */
#include "reference_cache.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "directory.h"
#include "renderer.h"

/* The reference program: "reference" beside this program (the Makefile builds both
 * into build/), and its cache folder "references" beside it. */
static void reference_program(char *program, char *directory, size_t size)
{
    char self[4096];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0 || (size_t)n >= sizeof self - 1)
        cli_fail(1, "cannot find this program's own path to find the reference program");
    self[n] = '\0';
    char *slash = strrchr(self, '/');
    *slash = '\0';
    if (snprintf(program, size, "%s/reference", self) >= (int)size ||
        snprintf(directory, size, "%s/references", self) >= (int)size)
        cli_fail(1, "path too long: %s", self);
}

/* The reference program's identity: its bytes and its modification time, so that a
 * rebuild (make rebuilds it whenever a lib/ file it links changes) renders every
 * reference again. */
static uint64_t program_identity(const char *program)
{
    int fd = open(program, O_RDONLY);
    struct stat status;
    if (fd < 0 || fstat(fd, &status) != 0)
        cli_fail(1, "cannot read the reference program %s: %s (build it: make %s)", program,
                 strerror(errno), program);
    uint64_t hash = MEASURE_HASH_START;
    char block[1 << 16];
    ssize_t n;
    while ((n = read(fd, block, sizeof block)) > 0)
        hash = measure_hash(hash, block, (size_t)n);
    close(fd);
    long long stamp[2] = {(long long)status.st_mtim.tv_sec, (long long)status.st_mtim.tv_nsec};
    return measure_hash(hash, stamp, sizeof stamp);
}

/* Run the reference program with `argv`, the scene's bytes on its standard input, with
 * this program's signals passed on to it (render_forward_signals). Returns its exit
 * status (128 + the signal if a signal ended it), or -1 with why in failure[size]. */
static int run_reference_program(char *const argv[], const char *scene_text,
                                 size_t scene_length, char *failure, size_t size)
{
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0) {
        snprintf(failure, size, "cannot start the reference program: %s", strerror(errno));
        return -1;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipe_ends[0], STDIN_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipe_ends[1]);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
    pid_t child;
    extern char **environ;
    render_hold_signals(1); /* none may come between the start and the forwarding */
    int spawn_error = posix_spawn(&child, argv[0], &actions, &attributes, argv, environ);
    if (spawn_error == 0)
        render_forward_signals(child);
    render_hold_signals(0);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    close(pipe_ends[0]);
    if (spawn_error != 0) {
        close(pipe_ends[1]);
        snprintf(failure, size, "cannot start the reference program %s: %s", argv[0],
                 strerror(spawn_error));
        return -1;
    }
    void (*previous)(int) = signal(SIGPIPE, SIG_IGN); /* a child that stops reading */
    for (size_t done = 0; done < scene_length;) {
        ssize_t n = write(pipe_ends[1], scene_text + done, scene_length - done);
        if (n <= 0 && errno != EINTR)
            break;
        done += n > 0 ? (size_t)n : 0;
    }
    close(pipe_ends[1]);
    signal(SIGPIPE, previous);
    int status = render_wait_for_child();
    if (status < 0)
        snprintf(failure, size, "lost the reference program: %s", strerror(errno));
    return status;
}

/* Hold the cache entry KEY: a lock on DIR/KEY.lock (its path in path[size]), waited for
 * while another program renders the same entry, so that it is rendered once; released
 * when the returned descriptor is closed, or when the program ends. Returns -1 with
 * errno set when the lock cannot be made, -2 when SIGINT stopped the wait. */
static int lock_entry(const char *directory, const char *key_text, char *path, size_t size)
{
    snprintf(path, size, "%s/%s.lock", directory, key_text);
    int fd = open(path, O_RDWR | O_CREAT, 0666);
    if (fd < 0)
        return -1;
    struct flock lock = {.l_type = F_WRLCK, .l_whence = SEEK_SET};
    while (fcntl(fd, F_SETLKW, &lock) != 0) {
        int reason = errno;
        if (reason == EINTR && !render_interrupted())
            continue;
        close(fd);
        errno = reason;
        return reason == EINTR ? -2 : -1;
    }
    return fd;
}

/* A new empty folder for a reference that is not to be kept, in $TMPDIR (or /tmp), its
 * path in folder[size]. Returns 0, or -1 with errno set. */
static int make_temporary_folder(char *folder, size_t size)
{
    const char *base = getenv("TMPDIR") && getenv("TMPDIR")[0] ? getenv("TMPDIR") : "/tmp";
    if (snprintf(folder, size, "%s/mc-reference-XXXXXX", base) >= (int)size) {
        errno = ENAMETOOLONG;
        return -1;
    }
    return mkdtemp(folder) ? 0 : -1;
}

/* Remove a temporary folder made for entry KEY, with whatever of the entry is in it. */
static void remove_temporary_folder(const char *folder, const char *key_text)
{
    const char *suffixes[] = {".pfm", "-stderr.pfm", ".txt", ".lock"};
    for (int i = 0; i < 4; i++) {
        char path[4300];
        snprintf(path, sizeof path, "%s/%s%s", folder, key_text, suffixes[i]);
        remove(path);
    }
    rmdir(folder);
}

/* Where a reference is looked for and rendered: the cache folder, or a temporary one
 * when the cache cannot be written; and a temporary one the reference program falls
 * back to when the cache fails it while it saves. */
typedef struct {
    char cache[4200];     /* where it is kept */
    char folder[4200];    /* where it is looked for and rendered: the cache, or temporary */
    char temporary[4200]; /* "" until made */
    char key_text[64];
    int lock;
} ReferencePlace;

/* Make the temporary folder, if not yet made; from then on a signal that ends the
 * program ends it only once the folder is removed (leave_place). Returns 0, or -1 with
 * errno set. */
static int make_place_temporary(ReferencePlace *place)
{
    if (place->temporary[0])
        return 0;
    render_forward_signals(0);
    if (make_temporary_folder(place->temporary, sizeof place->temporary) == 0)
        return 0;
    int reason = errno;
    place->temporary[0] = '\0';
    render_end_deferred();
    errno = reason;
    return -1;
}

/* Remove the temporary folder, if made, then end the program if a signal that ends it
 * came meanwhile. */
static void leave_place(ReferencePlace *place)
{
    if (place->temporary[0])
        remove_temporary_folder(place->temporary, place->key_text);
    place->temporary[0] = '\0';
    render_end_deferred();
}

/* Say that the cache cannot be written and why ("cannot write in FOLDER" or "cannot make
 * FILE", and errno's reason), and use a temporary folder instead. */
static void use_temporary_folder(ReferencePlace *place, const char *what, const char *path,
                                 int reason)
{
    printf("reference cache %s: %s %s: %s: rendering into a temporary folder, nothing is "
           "kept\n",
           place->cache, what, path, strerror(reason));
    if (make_place_temporary(place) != 0)
        cli_fail(1, "cannot make a temporary folder for the reference: %s", strerror(errno));
    snprintf(place->folder, sizeof place->folder, "%s", place->temporary);
}

/* The cache folder if it can be written, else a temporary one; locked for the key. */
static void open_reference_place(ReferencePlace *place)
{
    char failed[4096];
    snprintf(place->folder, sizeof place->folder, "%s", place->cache);
    if (directory_writable(place->cache, failed, sizeof failed) != 0)
        use_temporary_folder(place, "cannot write in", failed, errno);
    char lock_path[4300];
    place->lock = lock_entry(place->folder, place->key_text, lock_path, sizeof lock_path);
    if (place->lock == -1 && !place->temporary[0]) {
        use_temporary_folder(place, "cannot make", lock_path, errno);
        place->lock = lock_entry(place->folder, place->key_text, lock_path, sizeof lock_path);
    }
    int reason = errno;
    if (place->lock < 0)
        leave_place(place);
    if (place->lock == -2)
        cli_fail(130, "interrupted while waiting for another program to render the reference");
    if (place->lock < 0)
        cli_fail(1, "cannot lock %s: %s", lock_path, strerror(reason));
}

/* Render the reference into place->folder (the program falling back to the temporary
 * folder) and read it, or exit saying why. argv[argc] onwards has room for two words. */
static void render_reference(ReferencePlace *place, char **argv, int argc,
                             const char *scene_text, size_t scene_length,
                             const ReferenceIdentity *identity, int width, int height,
                             Reference *reference)
{
    if (render_interrupted()) {
        leave_place(place);
        cli_fail(130, "interrupted: stopped before rendering the reference");
    }
    /* Without a fallback folder the cache alone must take it. */
    if (strcmp(place->folder, place->cache) == 0 && make_place_temporary(place) == 0) {
        argv[argc++] = "--fallback";
        argv[argc++] = place->temporary;
    }
    argv[argc] = NULL;
    fflush(stdout);
    char failure[4400] = "", why[320];
    int exit_status =
        run_reference_program(argv, scene_text, scene_length, failure, sizeof failure);
    int status = -1;
    if (exit_status == 0) {
        status = measure_load_reference(place->folder, identity, width, height, reference, why,
                                        sizeof why);
        if (status == -1 && place->temporary[0] && strcmp(place->folder, place->temporary) != 0)
            status = measure_load_reference(place->temporary, identity, width, height,
                                            reference, why, sizeof why);
    }
    leave_place(place);
    if (exit_status == 130 || exit_status == 128 + SIGINT)
        cli_fail(130, "interrupted while rendering the reference; nothing was cached");
    if (exit_status < 0)
        cli_fail(1, "%s", failure);
    if (exit_status != 0)
        cli_fail(exit_status == 2 ? 2 : 1, "the reference program failed (exit status %d)",
                 exit_status);
    if (status != 0)
        cli_fail(1, "the reference program wrote no usable reference %s/%s.pfm (%s)",
                 place->folder, place->key_text, status == -1 ? "no entry" : why);
    reference->cached = 0;
}

void reference_cache_get(char *const *arguments, int count, const char *scene_text,
                         size_t scene_length, ReferenceIdentity *identity, int width,
                         int height, Reference *reference)
{
    char program[4200], parent[32];
    ReferencePlace place = {.temporary = ""};
    reference_program(program, place.cache, sizeof program);
    identity->key =
        measure_hash(identity->key, &(uint64_t){program_identity(program)}, sizeof(uint64_t));
    snprintf(place.key_text, sizeof place.key_text, "%016llx",
             (unsigned long long)identity->key);
    snprintf(parent, sizeof parent, "%ld", (long)getpid());
    char *argv[REFERENCE_CACHE_MAX_ARGUMENTS + 10] = {program};
    int argc = 1;
    for (int i = 0; i < count && i < REFERENCE_CACHE_MAX_ARGUMENTS; i++)
        argv[argc++] = arguments[i];
    char *place_arguments[] = {"--out",        place.folder, "--key",
                               place.key_text, "--parent",   parent};
    for (int i = 0; i < 6; i++)
        argv[argc++] = place_arguments[i];

    open_reference_place(&place);
    char why[320];
    int status = measure_load_reference(place.folder, identity, width, height, reference, why,
                                        sizeof why);
    if (status == -2)
        printf("reference cache: entry %s cannot be used (%s): rendering it again\n",
               place.key_text, why);
    if (status != 0)
        render_reference(&place, argv, argc, scene_text, scene_length, identity, width, height,
                         reference);
    close(place.lock);
    leave_place(&place);
}
