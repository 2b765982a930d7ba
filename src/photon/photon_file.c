/* SPDX-License-Identifier: MIT */
/*
** photon_file.c: saving and loading the caustic photon map (see
** photon_file.h).
**
** File layout (the writer's byte order; the byte-order word tells a file
** from a machine of the other order, which is refused by name):
**
**   offset  size        field
**        0     8        magic "IRISPHOT"
**        8     4        uint32 version (PHOTON_FILE_VERSION)
**       12     4        uint32 byte-order mark 0x01020304
**       16     4        uint32 record size (sizeof(struct pstore_photon))
**       20     4        uint32 L, the levels (pstore.h; 0 when n = 0)
**       24     8        uint64 n, the photons stored
**       32     8        uint64 photons emitted to build them
**       40    24        double lo[3], level 0's box corner
**       64    24        double step[3], level 0's root steps
**       88  64·L        per level: uint64 begin, uint64 n, double lo[3],
**                       double step[3] (the cells follow from the records)
**  88+64·L  16·n        the records, each level's in kd-tree order
**  ... +16·n    8        uint64 FNV-1a hash of every byte before it
**
** Why each check: the magic and version catch a foreign or older file;
** the record size a build whose pstore_photon changed; the exact file
** size (known from n before anything is allocated) a truncated file and
** a damaged n, which would otherwise ask for terabytes; the hash a
** damaged record, which the tree search would silently follow (a wrong
** axis, an out-of-box position); and each record's axis bits are checked
** again because the search trusts them. Every failure names the file and
** the scene's save_file/load_file keyword; none crashes.
**
** POV-Ray writes its own raw Photon structs; iris cannot read those (RGB
** photons, another layout) and says so through the magic check.
*/
#include "config.h"

#include "photon/photon_file.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "photon/pmap.h"
#include "util/mem.h"
#include "util/thread.h"

/* 2: positions over the kd cells of pstore.h (1: over one box) */
#define PHOTON_FILE_VERSION 2u
#define PHOTON_FILE_BOM 0x01020304u
#define PHOTON_FILE_HEADER 88
#define PHOTON_FILE_LEVEL 64
static const char MAGIC[8] = { 'I', 'R', 'I', 'S', 'P', 'H', 'O', 'T' };

/* The kd axis lives in bits 60..61 of 'pos' (pstore.h); 62..63 are 0. */
#define AXIS_SHIFT 60

/* FNV-1a, 64 bits: cheap, and any changed byte changes it. */
struct fnv {
    uint64_t h;
};

static void fnv_init(struct fnv *f)
{
    f->h = 0xcbf29ce484222325ULL;
}

static void fnv_add(struct fnv *f, const void *p, size_t n)
{
    const unsigned char *b = p;
    uint64_t h = f->h;
    for (size_t i = 0; i < n; i++) {
        h ^= b[i];
        h *= 0x100000001b3ULL;
    }
    f->h = h;
}

/* The header, packed into its 88 bytes (no struct padding questions). */
struct header {
    uint32_t version, bom, record, reserved;
    uint64_t n, shot;
    double lo[3], step[3];
};

static void header_pack(const struct header *h, unsigned char b[88])
{
    memcpy(b, MAGIC, 8);
    memcpy(b + 8, &h->version, 4);
    memcpy(b + 12, &h->bom, 4);
    memcpy(b + 16, &h->record, 4);
    memcpy(b + 20, &h->reserved, 4);
    memcpy(b + 24, &h->n, 8);
    memcpy(b + 32, &h->shot, 8);
    memcpy(b + 40, h->lo, 24);
    memcpy(b + 64, h->step, 24);
}

static void header_unpack(const unsigned char b[88], struct header *h)
{
    memcpy(&h->version, b + 8, 4);
    memcpy(&h->bom, b + 12, 4);
    memcpy(&h->record, b + 16, 4);
    memcpy(&h->reserved, b + 20, 4);
    memcpy(&h->n, b + 24, 8);
    memcpy(&h->shot, b + 32, 8);
    memcpy(h->lo, b + 40, 24);
    memcpy(h->step, b + 64, 24);
}

/* A level's 64 bytes (the records' range and its box). */
static void level_pack(const struct pstore_level *l,
                       unsigned char b[PHOTON_FILE_LEVEL])
{
    uint64_t begin = l->begin, n = l->n;
    memcpy(b, &begin, 8);
    memcpy(b + 8, &n, 8);
    memcpy(b + 16, l->lo, 24);
    memcpy(b + 40, l->step, 24);
}

/* Unpacks a level; returns false if it does not fit the store of 'n'
** records after the levels before it ('*next', the first record not yet
** covered) or its box is not finite. */
static bool level_unpack(const unsigned char b[PHOTON_FILE_LEVEL],
                         struct pstore_level *l, uint64_t n, uint64_t *next)
{
    uint64_t begin, cnt;
    memcpy(&begin, b, 8);
    memcpy(&cnt, b + 8, 8);
    memcpy(l->lo, b + 16, 24);
    memcpy(l->step, b + 40, 24);
    if (begin != *next || cnt == 0 || cnt > n - begin)
        return false;
    for (int a = 0; a < 3; a++)
        if (!isfinite(l->lo[a]) || !isfinite(l->step[a]) || l->step[a] < 0)
            return false;
    l->begin = (size_t)begin;
    l->n = (size_t)cnt;
    *next = begin + cnt;
    return true;
}

enum iris_status photon_file_save(const struct photon_map *m, long long shot,
                                  const char *path, char *err, size_t errlen)
{
    struct header h;
    memset(&h, 0, sizeof h);
    h.version = PHOTON_FILE_VERSION;
    h.bom = PHOTON_FILE_BOM;
    h.record = (uint32_t)sizeof(struct pstore_photon);
    h.shot = shot > 0 ? (uint64_t)shot : 0;
    const struct pstore_photon *ph = NULL;
    unsigned char lv[PSTORE_LEVELS][PHOTON_FILE_LEVEL];
    if (m && m->store.n > 0) {
        h.n = (uint64_t)m->store.n;
        ph = m->store.ph;
        memcpy(h.lo, m->store.lo, sizeof h.lo);
        memcpy(h.step, m->store.step, sizeof h.step);
        h.reserved = (uint32_t)m->store.n_levels;
        for (int l = 0; l < m->store.n_levels; l++)
            level_pack(&m->store.level[l], lv[l]);
    }
    unsigned char b[PHOTON_FILE_HEADER];
    header_pack(&h, b);
    struct fnv f;
    fnv_init(&f);
    fnv_add(&f, b, sizeof b);
    if (h.reserved)
        fnv_add(&f, lv, h.reserved * (size_t)PHOTON_FILE_LEVEL);
    if (ph)
        fnv_add(&f, ph, (size_t)h.n * sizeof *ph);
    /* written whole or not at all: a temporary file, then renamed */
    size_t tn = strlen(path) + 5;
    char *tmp = iris_malloc(tn);
    if (!tmp) {
        snprintf(err, errlen, "%s: out of memory", path);
        return IRIS_ENOMEM;
    }
    snprintf(tmp, tn, "%s.tmp", path);
    FILE *fp = fopen(tmp, "wb");
    int e = fp ? 0 : errno;
    bool ok = fp && fwrite(b, sizeof b, 1, fp) == 1 &&
              (!h.reserved ||
               fwrite(lv, PHOTON_FILE_LEVEL, h.reserved, fp) == h.reserved) &&
              (!ph || fwrite(ph, sizeof *ph, (size_t)h.n, fp) == h.n) &&
              fwrite(&f.h, sizeof f.h, 1, fp) == 1;
    if (fp && !ok)
        e = errno;
    if (fp && fclose(fp) != 0 && ok) {
        ok = false;
        e = errno;
    }
    if (ok && rename(tmp, path) != 0) {
        ok = false;
        e = errno;
    }
    if (!ok) {
        remove(tmp);
        snprintf(err, errlen, "cannot write the photon file \"%s\": %s", path,
                 e ? strerror(e) : "write error");
    }
    iris_free(tmp);
    return ok ? IRIS_OK : IRIS_EIO;
}

/* Reads and checks the file into 's' and *shot; message in 'err'. */
static enum iris_status read_store(const char *path, struct pstore *s,
                                   uint64_t *shot, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    FILE *fp = fopen(path, "rb");
    if (!fp) {
        snprintf(err, errlen, "cannot read the photon file \"%s\": %s", path,
                 strerror(errno));
        return IRIS_EIO;
    }
    const char *why = NULL;
    unsigned char b[PHOTON_FILE_HEADER];
    struct header h;
    memset(&h, 0, sizeof h);
    long long size = -1;
    if (fseek(fp, 0, SEEK_END) == 0)
        size = (long long)ftell(fp);
    rewind(fp);
    if (size < 0)
        why = "cannot tell its size";
    else if (size < 8 || fread(b, 8, 1, fp) != 1 || memcmp(b, MAGIC, 8) != 0)
        why = "not an iris photon file (no IRISPHOT magic)";
    else if (size < PHOTON_FILE_HEADER + 8 ||
             fread(b + 8, PHOTON_FILE_HEADER - 8, 1, fp) != 1)
        why = "truncated header";
    if (!why) {
        header_unpack(b, &h);
        if (h.bom != PHOTON_FILE_BOM)
            why = "written on a machine of another byte order";
        else if (h.version != PHOTON_FILE_VERSION)
            why = "another version of the format (this iris reads 2)";
        else if (h.record != sizeof(struct pstore_photon))
            why = "another photon record size (this iris uses 16 bytes)";
        else if (h.reserved > PSTORE_LEVELS || (h.reserved == 0) != (h.n == 0))
            why = "damaged header (its number of levels)";
        else {
            long long fixed = PHOTON_FILE_HEADER + 8 +
                              (long long)h.reserved * PHOTON_FILE_LEVEL;
            if (size < fixed ||
                h.n > (uint64_t)(size - fixed) / h.record ||
                (long long)(fixed + h.n * h.record) != size)
                why = size < (long long)(fixed + h.n * h.record)
                          ? "truncated (fewer photons than its header says)"
                          : "longer than its header says";
        }
        for (int a = 0; a < 3 && !why; a++)
            if (!isfinite(h.lo[a]) || !isfinite(h.step[a]) || h.step[a] < 0)
                why = "damaged header (a non-finite box)";
    }
    unsigned char lv[PSTORE_LEVELS][PHOTON_FILE_LEVEL];
    if (!why && h.reserved > 0) {
        if (fread(lv, PHOTON_FILE_LEVEL, h.reserved, fp) != h.reserved)
            why = "truncated (a read failed)";
        uint64_t next = 0;
        for (uint32_t l = 0; l < h.reserved && !why; l++)
            if (!level_unpack(lv[l], &s->level[l], h.n, &next))
                why = "damaged header (a level's range or box)";
        if (!why && next != h.n)
            why = "damaged header (the levels do not cover the photons)";
    }
    if (!why && h.n > 0) {
        s->ph = iris_malloc((size_t)h.n * sizeof *s->ph);
        if (!s->ph) {
            fclose(fp);
            snprintf(err, errlen, "%s: out of memory for %llu photons", path,
                     (unsigned long long)h.n);
            return IRIS_ENOMEM;
        }
        if (fread(s->ph, sizeof *s->ph, (size_t)h.n, fp) != h.n)
            why = "truncated (a read failed)";
    }
    uint64_t hash = 0;
    if (!why && fread(&hash, sizeof hash, 1, fp) != 1)
        why = "truncated (no hash)";
    fclose(fp);
    if (!why) {
        struct fnv f;
        fnv_init(&f);
        fnv_add(&f, b, sizeof b);
        if (h.reserved > 0)
            fnv_add(&f, lv, h.reserved * (size_t)PHOTON_FILE_LEVEL);
        if (h.n > 0)
            fnv_add(&f, s->ph, (size_t)h.n * sizeof *s->ph);
        if (f.h != hash)
            why = "damaged (its hash does not match its contents)";
    }
    for (uint64_t i = 0; !why && i < h.n; i++)
        if ((s->ph[i].pos >> AXIS_SHIFT) > 2 || !isfinite(s->ph[i].power))
            why = "damaged (a photon record is invalid)";
    if (why) {
        iris_free(s->ph);
        memset(s, 0, sizeof *s);
        snprintf(err, errlen, "photon file \"%s\": %s", path, why);
        return IRIS_EIO;
    }
    s->n = (size_t)h.n;
    s->n_levels = (int)h.reserved;
    memcpy(s->lo, h.lo, sizeof s->lo);
    memcpy(s->step, h.step, sizeof s->step);
    if (pstore_index_cells(s) != IRIS_OK) {
        pstore_fini(s);
        snprintf(err, errlen, "%s: out of memory for %llu photons", path,
                 (unsigned long long)h.n);
        return IRIS_ENOMEM;
    }
    *shot = h.shot;
    return IRIS_OK;
}

enum iris_status photon_file_load(const iris_scene *scene,
                                  const struct accel *accel,
                                  const struct photon_options *opts,
                                  const char *path, struct photon_map **out,
                                  struct photon_stats *stats, char *err,
                                  size_t errlen)
{
    *out = NULL;
    struct photon_stats st;
    memset(&st, 0, sizeof st);
    double t0 = par_now();
    struct photon_map *m = iris_calloc(1, sizeof *m);
    if (!m)
        return IRIS_ENOMEM;
    uint64_t shot = 0;
    enum iris_status rc = read_store(path, &m->store, &shot, err, errlen);
    if (rc != IRIS_OK) {
        photon_map_destroy(m);
        return rc;
    }
    m->scene = scene;
    pmap_caustic_setup(m, &scene->settings.photons, opts);
    double t1 = par_now();
    /* The global map, if radiosity{} wants one, as photon_map_build()
    ** makes it: a scene copy without photons{} builds the global map
    ** alone (hung off an empty caustic map, which is dropped). The copy
    ** is only read during the build. */
    iris_scene no_caustic = *scene;
    no_caustic.settings.photons.enabled = false;
    struct photon_map *shell = NULL;
    rc = photon_map_build(&no_caustic, accel, opts, &shell, &st);
    if (rc == IRIS_OK && shell) {
        m->global = shell->global;
        shell->global = NULL;
        if (m->global)
            m->global->scene = scene;
    }
    photon_map_destroy(shell);
    if (rc != IRIS_OK) {
        photon_map_destroy(m);
        if (err && errlen && !err[0])
            snprintf(err, errlen, "the global photon map: %s",
                     iris_status_str(rc));
        return rc;
    }
    st.shot = (int64_t)shot;
    st.stored = (int64_t)m->store.n;
    st.bytes += (int64_t)pstore_bytes(&m->store);
    st.gather_radius = m->radius;
    st.seconds_shoot = t1 - t0; /* the read */
    if (stats)
        *stats = st;
    *out = m;
    return IRIS_OK;
}
