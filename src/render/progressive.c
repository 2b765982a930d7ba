/* SPDX-License-Identifier: MIT */
/*
** progressive.c: progressive photon mapping (see progressive.h).
**
** DESIGN. A photon map of a fixed size is biased and stays biased: its
** estimate blurs the caustic over the gather radius however many times it
** is repeated. Knaus and Zwicker (2011) make the error vanish with
** INDEPENDENT passes whose radius shrinks, r_i^2 = r_1^2 ·
** prod_{k<i} (k + alpha)/(k + 1), alpha = 2/3, the images averaged: the
** bias falls with r^2 and the noise of the average still falls, as
** N^-1/3 each. A pass here is
**   1. a photon map built with pass = i (photon random streams keyed by
**      (seed, i, photon), cells sampled uniformly: shoot.c) whose
**      estimate radius is progressive_radius_scale(i) times the k-nearest
**      radius at the point (estimate.c explains why that per-point radius
**      needs no stored pilot);
**   2. an eye pass with new jitter: pass 0 is exactly the ordinary render
**      (pixel centres, the user's seed); later passes take one stratified
**      sample per pixel (when antialiasing is off) and a seed mixed from
**      (seed, pass), so every eye-side random stream is keyed by (seed,
**      pass, pixel);
**   3. the pass image added into a double-precision sum buffer.
** The map of pass i is freed before pass i+1 is built, so memory is one
** map plus two images whatever the pass count, except for small maps on
** two or more threads, where pass i+1's map is built during pass i's eye
** pass (PREFETCH below): then two small maps.
**
** Determinism: the maps and the eye pass do not depend on the thread
** count, and each pixel's sum adds the passes in order, so the image does
** not either. A checkpoint stores the sum buffer bit for bit; resuming
** continues with the next pass number, so checkpoint + resume gives the
** image an uninterrupted run with the same total passes gives.
**
** Checkpoint file (native byte order; a checkpoint is for the machine that
** wrote it): "IRISPPM1", then int32 width, height, passes; uint64 seed,
** photons; double seconds; then width·height·4 doubles (the RGBA sums,
** row 0 first). Written to FILE.tmp, then renamed.
**
** MPI (issue 8; mpi_passes.h). Under mpirun with R ranks the passes go
** in blocks of rounds of R passes, each rank adding its passes into its
** own sum buffer. The first block (one round, pass first + r on rank r)
** starts at once, without an agreement, so no rank waits for MPI_Init
** (which mpi_passes.c runs in the background) or for rank 0's pass 0
** map. At the end of a block the ranks agree: rank 0 decides (passes
** left, time limit, interrupt, the next block's length, a snapshot) and
** every rank learns the decision, the largest failure code and every
** rank's seconds per pass, in one non-blocking collective whose waiting
** rank sleeps rather than spins. With a time limit a block is one round,
** one pass per rank; with a fixed pass count blocks double from 1 up to
** about AGREE_EVERY_S of rounds (next_gap() says why) and their passes
** are shared in proportion to the ranks' speeds (block_share()). At the
** end the sums, pass and photon counts are reduced onto rank 0, which
** averages, reports the pass callback and writes the checkpoint. During
** the run rank 0 also gets a snapshot (the same reduction into a
** separate buffer) at an agreement when that costs at most
** 1/SNAPSHOT_COST_RATIO of the time, and reports it to the pass callback
** (error-log lines, intermediate images), so a long MPI run logs as it
** goes, from rank 0 only. Ranks other than 0 do not build pass 0's map
** (render.c); when rank 0's fails, rank 0 still joins the agreements to
** stop the others. A failure's message goes from the first failed rank
** to rank 0, which alone prints (mpi_passes_first_error), and a failed
** run writes no image at the end. A rank that stops before the passes
** (main.c) ends the whole job instead (mpi_passes_end_failed): the
** others would wait for it at their first agreement. A pass is the same
** whichever rank runs it, so the
** image equals the one-rank image up to the order of the double
** additions. On resume rank 0 reads the checkpoint and carries its sum;
** the other ranks start from zero at the next pass number. With R = 1
** nothing of this changes the run.
*/
#include "config.h"

#include "render/progressive.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "photon/photon.h"
#include "render/eyepass.h"
#include "render/mpi_passes.h"
#include "util/mem.h"
#include "util/rng.h"
#include "util/thread.h"

/* Seconds between checkpoint writes during a run (and one at the end). */
#define CHECKPOINT_EVERY_S 10.0

/* MPI: the pass callback (error log, intermediate images) runs on rank 0
** after a round when the time since the last such snapshot is at least
** this many times the last snapshot's reduction: at most 5% of the run
** goes into them (a 160x120 image reduces in ~1 ms, so then every round;
** a 4K image's 265 MB less often). */
#define SNAPSHOT_COST_RATIO 20.0

static const char CKPT_MAGIC[8] = { 'I', 'R', 'I', 'S', 'P', 'P', 'M', '1' };

bool progressive_wanted(const iris_render_options *opts)
{
    return opts->passes > 1 || opts->time_limit > 0.0 ||
           (opts->resume && opts->resume[0]);
}

double progressive_radius_scale(int pass)
{
    if (pass <= 0)
        return 1.0;
    const double a = PROGRESSIVE_ALPHA;
    if (pass < 1000) {
        double prod = 1.0;
        for (int k = 1; k <= pass; k++)
            prod *= (k + a) / (k + 1.0);
        return sqrt(prod);
    }
    /* prod_{k=1}^{p} (k+a)/(k+1) = Gamma(p+1+a) / (Gamma(1+a)·Gamma(p+2)) */
    double lp = lgamma(pass + 1.0 + a) - lgamma(1.0 + a) - lgamma(pass + 2.0);
    return sqrt(exp(lp));
}

/* err = "path: msg" */
static void set_err(char *err, size_t errlen, const char *path,
                    const char *msg)
{
    if (err && errlen)
        snprintf(err, errlen, "%s: %s", path, msg);
}

/* The accumulation: what a checkpoint holds. */
struct accum {
    int width, height, passes;
    uint64_t seed, photons;
    double seconds;            /* wall time of the runs before this one */
    double *sum;               /* width·height·4 */
};

static size_t accum_len(const struct accum *a)
{
    return (size_t)a->width * (size_t)a->height * 4;
}

static enum iris_status ckpt_write(const struct accum *a, const char *path)
{
    size_t n = strlen(path) + 5;
    char *tmp = iris_malloc(n);
    if (!tmp)
        return IRIS_ENOMEM;
    snprintf(tmp, n, "%s.tmp", path);
    FILE *f = fopen(tmp, "wb");
    bool ok = f != NULL;
    int32_t dims[3] = { a->width, a->height, a->passes };
    uint64_t u[2] = { a->seed, a->photons };
    ok = ok && fwrite(CKPT_MAGIC, 1, 8, f) == 8 &&
         fwrite(dims, sizeof dims, 1, f) == 1 &&
         fwrite(u, sizeof u, 1, f) == 1 &&
         fwrite(&a->seconds, sizeof a->seconds, 1, f) == 1 &&
         fwrite(a->sum, sizeof *a->sum, accum_len(a), f) == accum_len(a);
    if (f && fclose(f) != 0)
        ok = false;
    if (ok && rename(tmp, path) != 0)
        ok = false;
    if (!ok)
        remove(tmp);
    iris_free(tmp);
    return ok ? IRIS_OK : IRIS_EIO;
}

/* Reads a checkpoint into 'a' (its size and seed already set: they must
** match). */
static enum iris_status ckpt_read(struct accum *a, const char *path,
                                  char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        set_err(err, errlen, path, "cannot read the checkpoint");
        return IRIS_EIO;
    }
    char magic[8];
    int32_t dims[3];
    uint64_t u[2];
    double sec;
    bool ok = fread(magic, 1, 8, f) == 8 &&
              memcmp(magic, CKPT_MAGIC, 8) == 0 &&
              fread(dims, sizeof dims, 1, f) == 1 &&
              fread(u, sizeof u, 1, f) == 1 &&
              fread(&sec, sizeof sec, 1, f) == 1;
    if (!ok) {
        fclose(f);
        set_err(err, errlen, path, "not an iris checkpoint");
        return IRIS_EIO;
    }
    if (dims[0] != a->width || dims[1] != a->height || u[0] != a->seed ||
        dims[2] < 0 || !(sec >= 0.0) || !isfinite(sec)) {
        fclose(f);
        set_err(err, errlen, path,
                "the checkpoint was made with another image size or seed");
        return IRIS_EIO;
    }
    ok = fread(a->sum, sizeof *a->sum, accum_len(a), f) == accum_len(a);
    char extra;
    ok = ok && fread(&extra, 1, 1, f) == 0;
    fclose(f);
    for (size_t i = 0; ok && i < accum_len(a); i++)
        ok = isfinite(a->sum[i]);
    if (!ok) {
        set_err(err, errlen, path, "truncated or damaged checkpoint");
        return IRIS_EIO;
    }
    a->passes = dims[2];
    a->photons = u[1];
    a->seconds = sec;
    return IRIS_OK;
}

/* out = sum / passes (a partial first pass is left as it is). */
static void accum_average(const struct accum *a, iris_image *out)
{
    if (a->passes <= 0)
        return;
    double inv = 1.0 / a->passes;
    size_t n = accum_len(a);
    for (size_t i = 0; i < n; i++)
        out->pixels[i] = (float)(a->sum[i] * inv);
}

/* The seed of the eye pass of pass 'pass': the user's for pass 0. */
static uint64_t pass_seed(uint64_t seed, int pass)
{
    if (pass == 0)
        return seed;
    return rng_mix64(seed ^ rng_mix64(0x70617373ULL ^ rng_mix64(
                                          (uint64_t)pass)));
}

/*
** Replaces *map by pass 'pass''s map. The build reports its located
** errors to a log; rank 0's is stderr, but the other MPI ranks' stderr is
** /dev/null (main.c), so there the log goes to memory and its first line
** into 'err', which rank 0 prints (mpi_passes_first_error).
*/
static enum iris_status build_map_into(const iris_scene *scene,
                                       const struct accel *acc,
                                       const struct mat_ctx *mat,
                                       int threads, volatile int *interrupt,
                                       uint64_t seed, int pass,
                                       struct photon_map **map,
                                       struct photon_stats *ps, char *err,
                                       size_t errlen)
{
    *map = NULL;
    struct photon_options po;
    memset(&po, 0, sizeof po);
    po.threads = threads;
    po.seed = seed;
    po.pass = pass;
    po.radius_scale = progressive_radius_scale(pass);
    po.mat = mat;
    po.interrupt = interrupt;
    memset(ps, 0, sizeof *ps);
    char *logbuf = NULL;
    size_t loglen = 0;
    FILE *log = mpi_passes_rank() != 0 ? open_memstream(&logbuf, &loglen)
                                       : NULL;
    po.log = log;
    enum iris_status st = photon_map_build(scene, acc, &po, map, ps);
    if (log) {
        fclose(log); /* logbuf holds the text now */
        /* the first error line, without its newline */
        const char *e = logbuf ? strstr(logbuf, ": error: ") : NULL;
        if (st != IRIS_OK && e) {
            while (e > logbuf && e[-1] != '\n')
                e--;
            snprintf(err, errlen, "%.*s", (int)strcspn(e, "\n"), e);
        }
        free(logbuf);
    }
    return st;
}

static enum iris_status build_map(struct tracer *tr, const struct accel *acc,
                                  const struct mat_ctx *mat, int threads,
                                  uint64_t seed, int pass,
                                  struct photon_map **map,
                                  struct photon_stats *ps, char *err,
                                  size_t errlen)
{
    photon_map_destroy(*map);
    *map = NULL;
    tr->photon_map = NULL;
    enum iris_status st = build_map_into(tr->scene, acc, mat, threads,
                                         tr->interrupt, seed, pass, map, ps,
                                         err, errlen);
    tr->photon_map = *map;
    return st;
}

/*
** PREFETCH: the next pass's map built during this pass's eye pass, on a
** thread of its own with one thread (the map does not depend on the
** thread count, nor on anything the eye pass does: its random streams
** are keyed by seed and pass). Why: on two threads the photon phase of a
** pass scaled 1.65-1.69x against the eye pass's 1.92-1.99x (session 9,
** bench/scaling.sh): its serial steps (the quantisation box, the
** concatenation, the kd-tree's first median, the setup), its short
** parallel loops and their wake-ups. Built beside the eye pass, whose
** tiles the two pool threads take as they come, it costs the pass only
** its CPU time shared over the cores, and no serial step of its own.
** Only where the next pass is certain (a fixed --passes, no time limit;
** under MPI within this rank's block, or the next block with one rank)
** and for maps of at most PREFETCH_MAX_PHOTONS stored photons: two maps
** are alive meanwhile, and a large map's build is long and parallel
** anyway. IRIS_NO_PREFETCH=1 in the environment turns it off (A/B
** timing). A prefetch whose pass is not the one the loop then runs (an
** interrupt, a failure) is joined and discarded.
** It pays only while the map is ready when the eye pass ends: a map that
** costs more than the eye pass (many photons, a small image) would be
** built on one thread while the other waits. So when the loop has waited
** for the map more than PREFETCH_SLOW times the time of the eye pass it
** was built beside, two passes in a row, the run goes back to building
** each map on all the threads after the eye pass.
*/
#define PREFETCH_MAX_PHOTONS 1000000
#define PREFETCH_SLOW 0.05

struct prefetch {
    pthread_t tid;
    bool running;              /* started and not yet joined */
    int pass;
    const iris_scene *scene;
    const struct accel *acc;
    const struct mat_ctx *mat;
    volatile int *interrupt;
    uint64_t seed;
    struct photon_map *map;    /* the result, after the join */
    struct photon_stats ps;
    enum iris_status st;
    char err[512];
};

static void *prefetch_main(void *arg)
{
    struct prefetch *pf = arg;
    pf->st = build_map_into(pf->scene, pf->acc, pf->mat, 1, pf->interrupt,
                            pf->seed, pf->pass, &pf->map, &pf->ps, pf->err,
                            sizeof pf->err);
    return NULL;
}

/* Starts building pass 'pass''s map (nothing when a thread cannot be
** had: the loop then builds it itself). */
static void prefetch_start(struct prefetch *pf, const struct tracer *tr,
                           const struct accel *acc,
                           const struct mat_ctx *mat, uint64_t seed,
                           int pass)
{
    pf->pass = pass;
    pf->scene = tr->scene;
    pf->acc = acc;
    pf->mat = mat;
    pf->interrupt = tr->interrupt;
    pf->seed = seed;
    pf->map = NULL;
    pf->st = IRIS_OK;
    pf->err[0] = '\0';
    pf->running = pthread_create(&pf->tid, NULL, prefetch_main, pf) == 0;
}

/* Joins the prefetch; true when it built pass 'pass''s map (its status,
** map and stats are then the caller's), else its map is freed. */
static bool prefetch_take(struct prefetch *pf, int pass)
{
    if (!pf->running)
        return false;
    pthread_join(pf->tid, NULL);
    pf->running = false;
    if (pf->pass == pass)
        return true;
    photon_map_destroy(pf->map);
    pf->map = NULL;
    return false;
}

/* Whether to build pass 'q''s map during this pass's eye pass. */
static bool prefetch_wanted(const iris_render_options *opts, int threads,
                            int q, uint64_t stored)
{
    static int off = -1; /* IRIS_NO_PREFETCH, read once */
    if (off < 0) {
        const char *e = getenv("IRIS_NO_PREFETCH");
        off = e && *e && strcmp(e, "0") != 0;
    }
    return !off && threads >= 2 && q > 0 && opts->passes > 0 &&
           q < opts->passes && opts->time_limit <= 0.0 &&
           stored <= PREFETCH_MAX_PHOTONS &&
           !(opts->interrupt && *opts->interrupt);
}

/*
** MPI: every rank's sums so far onto rank 0 ('snap', NULL elsewhere),
** which reports their average to the pass callback. *cost gets the
** reduction's seconds, *last the time it ended.
*/
static void report_snapshot(const struct accum *a, double *snap,
                            const iris_render_options *opts,
                            iris_image *out, double t_start, double *cost,
                            double *last)
{
    double t0 = par_now();
    int passes = 0;
    uint64_t photons = 0;
    mpi_passes_snapshot(a->sum, snap, accum_len(a), a->passes, a->photons,
                        &passes, &photons);
    /* the smallest seen: a snapshot waits for the slowest rank too, and
    ** a loaded machine's one slow reduction must not stop the reports */
    double c = par_now() - t0;
    if (*cost <= 0.0 || c < *cost)
        *cost = c;
    if (snap && passes > 0) {
        struct accum all = *a;
        all.sum = snap;
        all.passes = passes;
        accum_average(&all, out);
        iris_pass_info info = { passes, a->seconds + (par_now() - t_start),
                                photons, progressive_radius_scale(passes - 1) };
        opts->on_pass(opts->on_pass_user, out, &info);
    }
    *last = par_now();
}

/* Should the loop start pass 'pass'? */
static bool another_pass(const iris_render_options *opts, int pass,
                         int first, double elapsed, double last_dt)
{
    if (opts->interrupt && *opts->interrupt)
        return false;
    if (opts->passes > 0 && pass >= opts->passes)
        return false;
    if (opts->passes <= 0 && opts->time_limit <= 0.0)
        return pass == first; /* --resume alone: one more pass */
    /* The time limit: stop when the next pass, as long as the last one,
    ** would end past it; this run always does at least one pass */
    if (opts->time_limit > 0.0 && pass > first &&
        elapsed + last_dt > opts->time_limit)
        return false;
    return true;
}

/*
** MPI: the rounds rank 0 grants until the next agreement. Every
** agreement is a barrier: all ranks wait there for the slowest, and a
** pass's time varies (the photon count, the machine's other load), so
** one agreement a round cost each round the spread of its passes. With a
** fixed pass count the ranks need to agree only to stop early (interrupt,
** failure) and for snapshots: the gap doubles from 1 up to about
** AGREE_EVERY_S of rounds ('round_s' is the last gap's time per round),
** and ends at the last round. With a time limit rank 0 decides every
** round, as before.
*/
#define AGREE_EVERY_S 5.0

static int next_gap(const iris_render_options *opts, int gap, int base,
                    int nranks, double round_s)
{
    if (opts->passes <= 0 || opts->time_limit > 0.0 || nranks <= 1)
        return 1;
    int left = (opts->passes - base + nranks - 1) / nranks;
    int g = gap <= 0 ? 1 : 2 * gap;
    if (round_s > 0.0 && g > 1 && g * round_s > AGREE_EVERY_S)
        g = (int)fmax(1.0, AGREE_EVERY_S / round_s);
    return left < 1 ? 1 : g > left ? left : g;
}

/*
** MPI: which passes of a block this rank runs. A block is 'blk' = gap·R
** passes from 'next' (fewer past --passes). The first block, a time
** limit (rank 0 decides round by round) and more than SHARE_MAX_RANKS
** ranks: pass next + r + j·R on rank r, one a round. Otherwise the
** ranks' speeds (each[r]: rank r's microseconds per pass so far, 0
** unknown) share the block: rank r runs a contiguous run of passes in
** proportion to 1/each[r], rounded by largest remainder (ties to the
** lower rank), so a rank slowed by the machine's other load, or rank 0
** by its snapshots, gets fewer passes and the ranks reach the next
** agreement together. Every rank computes the same shares from the same
** agreed numbers. Which rank runs a pass does not change the pass (its
** random streams are keyed by its number), only the order in which the
** double sums add up.
*/
#define SHARE_MAX_RANKS 256

static void block_share(const iris_render_options *opts, int next, int blk,
                        int rank, int nranks, const int *each, int *lo,
                        int *n, int *stride)
{
    bool known = each != NULL && opts->time_limit <= 0.0 &&
                 opts->passes > 0;
    for (int r = 0; known && r < nranks; r++)
        known = each[r] > 0;
    if (!known) {
        *lo = next + rank;
        *n = blk / nranks;
        *stride = nranks;
        return;
    }
    int k = opts->passes - next < blk ? opts->passes - next : blk;
    if (k < 0)
        k = 0;
    double vsum = 0.0;
    for (int r = 0; r < nranks; r++)
        vsum += 1.0 / each[r];
    /* floors first, then the remainders by size */
    int given = 0, start = next;
    int cnt[SHARE_MAX_RANKS];
    double frac[SHARE_MAX_RANKS];
    for (int r = 0; r < nranks; r++) {
        double x = k * (1.0 / each[r]) / vsum;
        cnt[r] = (int)floor(x);
        frac[r] = x - cnt[r];
        given += cnt[r];
    }
    while (given < k) {
        int best = 0;
        for (int r = 1; r < nranks; r++)
            if (frac[r] > frac[best])
                best = r;
        cnt[best]++;
        frac[best] = -1.0;
        given++;
    }
    for (int r = 0; r < rank; r++)
        start += cnt[r];
    *lo = start;
    *n = cnt[rank];
    *stride = 1;
}

/* MPI: where a rank's time went (opts->rank_times, bench/scaling.sh). */
struct rank_times {
    double work_s;             /* its passes: maps and eye passes */
    double agree_s;            /* the agreements, waiting included */
    double snapshot_s;         /* rank 0's snapshots, the others' share */
    double reduce_s;           /* the final reduction, waiting included */
    int agreements;            /* how many */
    int prefetched;            /* maps built during an eye pass (PREFETCH) */
};

/*
** With opts->rank_times set (the iris command: IRIS_RANK_TIMES in the
** environment), rank 0 prints every rank's times there: "iris: rank R: P
** passes, work W s, N agreements A s, snapshots S s, final reduce F s,
** prefetched M maps, total T s, cpu C s" (one line without MPI; M: the
** maps built during the previous eye pass, PREFETCH). A rank that waits
** long at the final reduction finished early: the load was uneven. C is
** the process's CPU time since it started (MPI_Init, parse and build
** included; waits sleep, so they add little): on a loaded machine,
** where wall times mislead, the largest C is the run's critical path
** (bench/scaling.sh).
*/
static double cpu_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void report_rank_times(FILE *to, const struct rank_times *rt,
                              int passes, double total_s)
{
    if (!to)
        return;
    enum { MAX_RANKS = 256 }; /* a table, not a cluster's log */
    int n = mpi_passes_size();
    if (n > MAX_RANKS)
        return;
    enum { K = 9 };
    double mine[K] = { passes, rt->work_s, rt->agreements, rt->agree_s,
                       rt->snapshot_s, rt->reduce_s, rt->prefetched,
                       total_s, cpu_seconds() };
    double all[K * MAX_RANKS];
    mpi_passes_gather(mine, K, all);
    for (int r = 0; mpi_passes_rank() == 0 && r < n; r++) {
        const double *v = all + K * r;
        fprintf(to, "iris: rank %d: %.0f passes, work %.3f s, %.0f "
                "agreements %.3f s, snapshots %.3f s, final reduce %.3f s, "
                "prefetched %.0f maps, total %.3f s, cpu %.3f s\n", r, v[0],
                v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
    }
}

enum iris_status progressive_run(struct tracer *tr, const struct accel *acc,
                                 const struct mat_ctx *mat, int threads,
                                 const iris_render_options *opts,
                                 double t_start, enum iris_status pass0,
                                 struct photon_map **map,
                                 iris_image *out, iris_render_stats *stats,
                                 double *photon_s, char *err, size_t errlen)
{
    *photon_s = 0.0;
    struct accum a;
    memset(&a, 0, sizeof a);
    a.width = out->width;
    a.height = out->height;
    a.seed = opts->seed;
    a.photons = stats ? stats->photons_emitted : 0;
    a.sum = iris_calloc(accum_len(&a), sizeof *a.sum);
    iris_image img;
    memset(&img, 0, sizeof img);
    enum iris_status st = a.sum ? iris_image_init(&img, a.width, a.height)
                                : IRIS_ENOMEM;
    bool photons = tr->photon_shade != NULL;
    const int rank = mpi_passes_rank(), nranks = mpi_passes_size();
    if (rank != 0) /* pass 0 and its photons are rank 0's */
        a.photons = 0;
    if (st == IRIS_OK && opts->resume && opts->resume[0]) {
        int got[2] = { IRIS_OK, 0 };
        if (rank == 0) {
            got[0] = ckpt_read(&a, opts->resume, err, errlen);
            got[1] = a.passes;
        }
        mpi_passes_bcast_int(got, 2);
        st = (enum iris_status)got[0];
        a.passes = got[1]; /* the other ranks: only the pass number */
        /* pass 0's map (built by the caller) is not needed any more */
        if (st == IRIS_OK && photons && a.passes > 0) {
            photon_map_destroy(*map);
            *map = NULL;
            tr->photon_map = NULL;
        }
    }
    if (st != IRIS_OK) {
        iris_free(a.sum);
        iris_image_fini(&img);
        if (st == IRIS_ENOMEM)
            set_err(err, errlen, "progressive", "out of memory");
        return st;
    }
    if (a.passes > 0)
        accum_average(&a, out);
    bool failed = false;
    if (pass0 != IRIS_OK) { /* MPI: rank 0 only stops the others */
        st = pass0;
        failed = true;
    }

    const uint64_t seed0 = tr->seed;
    int first = a.passes;
    if (rank != 0)
        a.passes = 0; /* counts this rank's passes, reduced at the end */
    double last_ckpt = par_now(), last_dt = 0.0;
    uint64_t stored = stats ? stats->photons_stored : 0;
    uint64_t bytes = stats ? stats->photon_bytes : 0;
    iris_render_stats es_sum;
    memset(&es_sum, 0, sizeof es_sum);
    double *snap = NULL; /* rank 0's snapshot buffer (MPI) */
    if (rank == 0 && nranks > 1 && opts->on_pass)
        snap = iris_malloc(accum_len(&a) * sizeof *snap);
    double last_snap = par_now(), snap_cost = 0.0;
    struct rank_times rt = { 0, 0, 0, 0, 0, 0 };
    /* MPI: the first block starts without an agreement. Whether it runs
    ** depends only on --passes and 'first', which every rank knows; a
    ** failure or an interrupt in it stops all at the next agreement. So
    ** no rank waits for rank 0's pass 0 map (render.c) or for MPI_Init's
    ** end (mpi_passes.c) before its first pass. */
    int gap = 0; /* rounds of R passes in this block */
    bool agree_now = true;
    if (nranks > 1 && !(opts->passes > 0 && first >= opts->passes)) {
        gap = 1;
        agree_now = false;
    }
    int other_failed = 0; /* rank 0: the largest failure code of a rank */
    /* this rank's seconds per pass, from the passes whose whole cost it
    ** measured (rank 0's pass 0 map was built in render.c), its
    ** snapshots included */
    double rate_s = 0.0;
    int rate_n = 0;
    int each_buf[SHARE_MAX_RANKS] = { 0 };
    /* MPI: every rank's microseconds per pass (the same on all ranks) */
    int *each = nranks > 1 && nranks <= SHARE_MAX_RANKS ? each_buf : NULL;
    double last_agree = par_now();
    struct prefetch pf;
    memset(&pf, 0, sizeof pf);
    int pf_slow = 0;           /* prefetched passes in a row that waited */
    bool pf_off = false;       /* too slow: not any more this run */
    double eye_s = 0.0;        /* the last eye pass's seconds */
    for (int next = first;; ) {
        if (agree_now) {
            /* The block of passes from 'next' up to the next agreement,
            ** decided by rank 0, whether to report a snapshot of the
            ** blocks before it, and every rank's speed */
            double ta = par_now();
            int go = rank == 0 &&
                     another_pass(opts, next, first, ta - t_start, last_dt);
            int vals[2] = {
                snap && next > first &&
                    ta - last_snap >= SNAPSHOT_COST_RATIO * snap_cost,
                rank == 0 ? next_gap(opts, gap, next, nranks,
                                     (ta - last_agree) / (gap > 0 ? gap : 1))
                          : 0 };
            /* failure codes: 1 interrupted, else 1 + the status */
            int code = failed ? 1 + (int)(st != IRIS_OK ? st : IRIS_EINTR)
                       : opts->interrupt && *opts->interrupt ? 1
                                                             : 0;
            if (each)
                each[rank] = rate_n > 0 ? (int)fmin(1e9, fmax(1.0,
                                 1e6 * rate_s / rate_n)) : 0;
            bool more = mpi_passes_agree(go, code, vals, 2, each,
                                         &other_failed);
            last_agree = par_now();
            rt.agree_s += last_agree - ta;
            rt.agreements++;
            if (!more)
                break;
            if (vals[0]) {
                report_snapshot(&a, snap, opts, out, t_start, &snap_cost,
                                &last_snap);
                rt.snapshot_s += par_now() - last_agree;
                /* rank 0's snapshots (an image write) slow its blocks */
                rate_s += par_now() - last_agree;
            }
            gap = vals[1] > 0 ? vals[1] : 1;
        }
        agree_now = true;
        /* this rank's passes of the block: p = lo + j·stride, j < n */
        int blk = gap * nranks, lo, n_mine, stride;
        block_share(opts, next, blk, rank, nranks, each, &lo, &n_mine,
                    &stride);
        next += blk;
        for (int j = 0; j < n_mine; j++) {
            int p = lo + j * stride;
            if (nranks > 1 && !another_pass(opts, p, first, 0.0, 0.0))
                continue; /* past --passes (or --resume's one pass) */
            if (failed) /* this rank waits for the next agreement to stop */
                continue;
            double tp = par_now();
            bool whole = !photons || p > 0 || *map == NULL;
            if (photons && (p > 0 || *map == NULL)) {
                struct photon_stats ps;
                if (prefetch_take(&pf, p)) { /* built meanwhile */
                    /* waited longer than its eye pass can hide? */
                    pf_slow = par_now() - tp > PREFETCH_SLOW * eye_s
                                  ? pf_slow + 1 : 0;
                    pf_off = pf_off || pf_slow >= 2;
                    rt.prefetched++;
                    photon_map_destroy(*map);
                    *map = pf.map;
                    tr->photon_map = pf.map;
                    pf.map = NULL;
                    ps = pf.ps;
                    st = pf.st;
                    if (st != IRIS_OK && err && errlen)
                        snprintf(err, errlen, "%s", pf.err);
                } else {
                    st = build_map(tr, acc, mat, threads, opts->seed, p,
                                   map, &ps, err, errlen);
                }
                if (st != IRIS_OK) {
                    failed = true; /* the next agreement stops all */
                    continue;
                }
                a.photons += (uint64_t)ps.shot;
                stored = (uint64_t)ps.stored;
                if ((uint64_t)ps.bytes > bytes)
                    bytes = (uint64_t)ps.bytes;
                *photon_s += par_now() - tp;
            }
            /* the next pass of this rank: the block's next, or with one
            ** rank the next block's (one pass a block) */
            int q = j + 1 < n_mine ? lo + (j + 1) * stride
                    : nranks == 1  ? next
                                   : -1;
            if (photons && !pf_off &&
                prefetch_wanted(opts, threads, q, stored))
                prefetch_start(&pf, tr, acc, mat, opts->seed, q);
            iris_render_options po = *opts;
            po.progress = NULL;
            po.plan_out = NULL;
            po.seed = pass_seed(opts->seed, p);
            if (p > 0 && po.aa == IRIS_AA_NONE) {
                /* one jittered sample per pixel */
                po.aa = IRIS_AA_STRATIFIED;
                po.aa_depth = 1;
            }
            tr->seed = po.seed;
            iris_render_stats es;
            memset(&es, 0, sizeof es);
            double te = par_now();
            st = eyepass_run(tr, &po, threads, &img, &es);
            eye_s = par_now() - te;
            es_sum.rays_traced += es.rays_traced;
            es_sum.rays += es.rays;
            es_sum.rays_camera += es.rays_camera;
            es_sum.rays_reflected += es.rays_reflected;
            es_sum.rays_refracted += es.rays_refracted;
            es_sum.rays_transmitted += es.rays_transmitted;
            es_sum.shadow_tests += es.shadow_tests;
            es_sum.shadow_hits += es.shadow_hits;
            es_sum.nan_pixels += es.nan_pixels;
            es_sum.time_render_cpu_s += es.time_render_cpu_s;
            es_sum.threads = es.threads;
            if (st != IRIS_OK) {
                if (st == IRIS_EINTR && a.passes == 0) /* partial image */
                    memcpy(out->pixels, img.pixels,
                           accum_len(&a) * sizeof *img.pixels);
                failed = true;
                continue;
            }
            size_t n = accum_len(&a);
            for (size_t i = 0; i < n; i++)
                a.sum[i] += img.pixels[i];
            a.passes++;
            accum_average(&a, out);
            double now = par_now();
            last_dt = now - tp;
            rt.work_s += last_dt;
            if (whole) {
                rate_s += last_dt;
                rate_n++;
            }
            if (opts->on_pass && nranks == 1) { /* MPI: once, at the end */
                iris_pass_info info = { a.passes,
                                        a.seconds + (now - t_start),
                                        a.photons,
                                        progressive_radius_scale(p) };
                opts->on_pass(opts->on_pass_user, out, &info);
            }
            if (opts->progress) {
                double tl = opts->time_limit;
                opts->progress(opts->progress_user, "passes",
                               opts->passes > 0
                                   ? (double)(p + 1) / opts->passes
                               : tl > 0.0 ? fmin(1.0, (now - t_start) / tl)
                                          : 1.0);
            }
            if (opts->checkpoint && opts->checkpoint[0] && nranks == 1 &&
                now - last_ckpt >= CHECKPOINT_EVERY_S) {
                double keep = a.seconds;
                a.seconds += now - t_start;
                enum iris_status cs = ckpt_write(&a, opts->checkpoint);
                a.seconds = keep;
                last_ckpt = now;
                if (cs != IRIS_OK) {
                    set_err(err, errlen, opts->checkpoint,
                            "cannot write the checkpoint");
                    st = cs;
                    failed = true;
                    continue;
                }
            }
        }
    }
    prefetch_take(&pf, -1); /* a pass the loop did not run */
    tr->seed = seed0;
    iris_free(snap);
    /* MPI: a rank failed (codes > 1; 1 is an interrupt). Every rank knows
    ** it from the last agreement, so all take part in sending the first
    ** failed rank's message to rank 0, which alone can print it. */
    int err_rank = -1;
    if (nranks > 1 && other_failed > 1)
        err_rank = mpi_passes_first_error(failed && st != IRIS_OK &&
                                              st != IRIS_EINTR,
                                          err, errlen);
    if (st == IRIS_OK && other_failed > 1 && rank == 0) {
        /* another rank failed: so does the run, with that rank's status
        ** and its message (located when the rank had one: a photon
        ** pass's memory check) */
        st = (enum iris_status)(other_failed - 1);
        char msg[400];
        snprintf(msg, sizeof msg, "%s", err ? err : "");
        if (err && errlen && msg[0])
            snprintf(err, errlen, "%s (MPI rank %d)", msg, err_rank);
        else
            set_err(err, errlen, "progressive",
                    st == IRIS_ENOMEM ? "another MPI rank ran out of memory"
                    : st == IRIS_EINVAL
                        ? "another MPI rank's photon pass exceeded its "
                          "memory share"
                        : "another MPI rank failed");
    }
    if (nranks > 1) {
        /* rank 0 gets the sum of every rank's passes */
        double tr0 = par_now();
        int my_passes = a.passes;
        mpi_passes_reduce(a.sum, accum_len(&a), &a.passes, &a.photons);
        rt.reduce_s = par_now() - tr0;
        report_rank_times(opts->rank_times, &rt, my_passes,
                          par_now() - t_start);
        if (rank == 0) {
            accum_average(&a, out);
            /* a failed run writes no image of its own at the end (the
            ** ones written as it went stay, as with one rank) */
            if (opts->on_pass && a.passes > 0 &&
                (st == IRIS_OK || st == IRIS_EINTR)) {
                iris_pass_info info = { a.passes,
                                        a.seconds + (par_now() - t_start),
                                        a.photons,
                                        progressive_radius_scale(
                                            a.passes - 1) };
                opts->on_pass(opts->on_pass_user, out, &info);
            }
        }
    } else {
        report_rank_times(opts->rank_times, &rt, a.passes,
                          par_now() - t_start);
    }
    if (st == IRIS_OK && opts->interrupt && *opts->interrupt)
        st = IRIS_EINTR;
    /* The checkpoint at the end, of the passes completed (interrupted or
    ** not) */
    if ((st == IRIS_OK || st == IRIS_EINTR) && opts->checkpoint &&
        opts->checkpoint[0] && a.passes > 0 && rank == 0) {
        a.seconds += par_now() - t_start;
        if (ckpt_write(&a, opts->checkpoint) != IRIS_OK) {
            set_err(err, errlen, opts->checkpoint,
                    "cannot write the checkpoint");
            st = IRIS_EIO;
        }
    }
    if (stats) {
        stats->passes = a.passes;
        stats->photons_emitted = a.photons;
        stats->photons_stored = stored;
        stats->photon_bytes = bytes;
        stats->rays_traced += es_sum.rays_traced;
        stats->rays += es_sum.rays;
        stats->rays_camera += es_sum.rays_camera;
        stats->rays_reflected += es_sum.rays_reflected;
        stats->rays_refracted += es_sum.rays_refracted;
        stats->rays_transmitted += es_sum.rays_transmitted;
        stats->shadow_tests += es_sum.shadow_tests;
        stats->shadow_hits += es_sum.shadow_hits;
        stats->nan_pixels += es_sum.nan_pixels;
        stats->time_render_cpu_s += es_sum.time_render_cpu_s;
        stats->threads = es_sum.threads ? es_sum.threads : threads;
    }
    iris_free(a.sum);
    iris_image_fini(&img);
    return st;
}
