/* reference_cache.h (bench, chapter 2): the references the chapter programs measure
 * against, cached in build/references/ and rendered by build/reference when missing.
 *
 * An entry is named by a key that hashes the scene's bytes, the settings the reference
 * estimates with and the reference program's own bytes and time, so a rebuild of that
 * program renders every reference again. One program renders an entry while any other
 * that wants it waits on its lock; where the cache cannot be written, a temporary folder
 * takes the reference, and nothing is kept. The reference program runs as a child of
 * this one, the scene's bytes on its standard input and this program's signals passed on.
 */
#ifndef REFERENCE_CACHE_H
#define REFERENCE_CACHE_H

#include "measure.h"

/* The most arguments reference_cache_get passes on besides its own. */
#define REFERENCE_CACHE_MAX_ARGUMENTS 24

/* The reference `identity` names, width x height: identity->key hashes the scene and its
 * settings, to which the reference program's identity is added here. Read from the cache
 * folder "references" beside this program, or rendered first by the program "reference"
 * beside it with `arguments` (then --out, --key and --parent, which name the entry), the
 * scene_length bytes of scene_text on its standard input. On any failure, exits as
 * cli_fail does: 130 when interrupted, 2 when the program refuses its arguments, else 1. */
void reference_cache_get(char *const *arguments, int count, const char *scene_text,
                         size_t scene_length, ReferenceIdentity *identity, int width,
                         int height, Reference *reference);

#endif
