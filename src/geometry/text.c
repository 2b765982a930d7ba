/* SPDX-License-Identifier: MIT */
/*
** text.c: the glyph outlines of a text object, through FreeType.
**
** Each glyph's outline (in font units, scaled so that one em is 1 unit as
** POV-Ray scales it) is flattened to segments, one group per contour, and
** placed along the baseline by the glyph advance, kerning and the
** object's 'offset'. sweep.c extrudes the result from z = 0 to z =
** thickness, so text is an exact prism of the flattened outline rather
** than a triangle mesh.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

/* Straight pieces per quadratic or cubic outline arc: the chord error is
** about 1/(8·64) of the arc's bulge, invisible at text sizes. */
#define ARC_STEPS 8

/* Where POV-Ray's own fonts live (configure finds povray-includes). */
#ifdef POVRAY_INCLUDE_DIR
#define POV_FONT_DIR POVRAY_INCLUDE_DIR
#else
#define POV_FONT_DIR "/usr/share/povray-3.7/include"
#endif

struct outline_ctx {
    struct geom_profile *p;
    double scale, dx, dy;
    iris_vec2 cur, first;
    bool open, ok;
};

static iris_vec2 pt(const struct outline_ctx *c, const FT_Vector *v)
{
    iris_vec2 r = { c->dx + v->x * c->scale, c->dy + v->y * c->scale };
    return r;
}

static void line(struct outline_ctx *c, iris_vec2 b)
{
    if (c->ok && !geom_profile_add(c->p, c->cur, b))
        c->ok = false;
    c->cur = b;
}

static void close_contour(struct outline_ctx *c)
{
    if (c->open) {
        line(c, c->first);
        if (c->ok && !geom_profile_close_group(c->p))
            c->ok = false;
    }
    c->open = false;
}

static int move_to(const FT_Vector *to, void *user)
{
    struct outline_ctx *c = user;
    close_contour(c);
    c->cur = c->first = pt(c, to);
    c->open = true;
    return 0;
}

static int line_to(const FT_Vector *to, void *user)
{
    struct outline_ctx *c = user;
    line(c, pt(c, to));
    return 0;
}

static int conic_to(const FT_Vector *ctl, const FT_Vector *to, void *user)
{
    struct outline_ctx *c = user;
    iris_vec2 a = c->cur, b = pt(c, ctl), e = pt(c, to);
    for (int i = 1; i <= ARC_STEPS; i++) {
        double s = (double)i / ARC_STEPS, r = 1 - s;
        iris_vec2 q = { r * r * a.u + 2 * r * s * b.u + s * s * e.u,
                        r * r * a.v + 2 * r * s * b.v + s * s * e.v };
        line(c, q);
    }
    return 0;
}

static int cubic_to(const FT_Vector *c1, const FT_Vector *c2,
                    const FT_Vector *to, void *user)
{
    struct outline_ctx *c = user;
    iris_vec2 a = c->cur, b = pt(c, c1), d = pt(c, c2), e = pt(c, to);
    for (int i = 1; i <= ARC_STEPS; i++) {
        double s = (double)i / ARC_STEPS, r = 1 - s;
        double w0 = r * r * r, w1 = 3 * r * r * s, w2 = 3 * r * s * s;
        double w3 = s * s * s;
        iris_vec2 q = { w0 * a.u + w1 * b.u + w2 * d.u + w3 * e.u,
                        w0 * a.v + w1 * b.v + w2 * d.v + w3 * e.v };
        line(c, q);
    }
    return 0;
}

/* Next code point of UTF-8 string '*s' (invalid bytes read as Latin-1). */
static unsigned long utf8_next(const unsigned char **s)
{
    const unsigned char *p = *s;
    unsigned long c = *p++;
    int extra = c >= 0xf0 ? 3 : c >= 0xe0 ? 2 : c >= 0xc0 ? 1 : 0;
    unsigned long v = extra == 3 ? c & 7 : extra == 2 ? c & 15 : c & 31;
    if (extra == 0) {
        *s = p;
        return c;
    }
    for (int i = 0; i < extra; i++) {
        if ((p[i] & 0xc0) != 0x80) {
            *s = *s + 1;
            return c;
        }
        v = (v << 6) | (p[i] & 0x3f);
    }
    *s = p + extra;
    return v;
}

/*
** The box a TrueType glyph's 'glyf' entry stores in its header (font
** units): POV-Ray reads it, then widens it by the outline's points, and
** places and boxes the glyph by the result; a font may store a box wider
** than its points. An empty glyph (a space) has the box 0. False when
** the face has no such tables (the caller then uses the points' box).
*/
static bool glyf_header_box(FT_Face face, FT_UInt gi, FT_BBox *box)
{
    TT_Header *head = FT_IS_SFNT(face)
                          ? FT_Get_Sfnt_Table(face, FT_SFNT_HEAD) : NULL;
    if (!head)
        return false;
    FT_Byte b[10];
    FT_ULong len, off0, off1;
    if (head->Index_To_Loc_Format == 0) {
        len = 4; /* 16-bit offsets, in units of 2 bytes */
        if (FT_Load_Sfnt_Table(face, TTAG_loca, (FT_Long)gi * 2, b, &len))
            return false;
        off0 = (FT_ULong)((b[0] << 8) | b[1]) * 2;
        off1 = (FT_ULong)((b[2] << 8) | b[3]) * 2;
    } else {
        len = 8;
        if (FT_Load_Sfnt_Table(face, TTAG_loca, (FT_Long)gi * 4, b, &len))
            return false;
        off0 = ((FT_ULong)b[0] << 24) | ((FT_ULong)b[1] << 16) |
               ((FT_ULong)b[2] << 8) | b[3];
        off1 = ((FT_ULong)b[4] << 24) | ((FT_ULong)b[5] << 16) |
               ((FT_ULong)b[6] << 8) | b[7];
    }
    box->xMin = box->yMin = box->xMax = box->yMax = 0;
    if (off1 <= off0)
        return true;
    len = 10; /* numberOfContours, xMin, yMin, xMax, yMax: int16 each */
    if (FT_Load_Sfnt_Table(face, TTAG_glyf, (FT_Long)off0, b, &len))
        return false;
    box->xMin = (int16_t)((b[2] << 8) | b[3]);
    box->yMin = (int16_t)((b[4] << 8) | b[5]);
    box->xMax = (int16_t)((b[6] << 8) | b[7]);
    box->yMax = (int16_t)((b[8] << 8) | b[9]);
    return true;
}

/* Opens the font file, trying POV-Ray's font directory for bare names. */
static FT_Error open_face(FT_Library lib, const char *path, FT_Face *face)
{
    FT_Error e = FT_New_Face(lib, path, 0, face);
    if (!e)
        return 0;
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    char buf[1024];
    if (!POV_FONT_DIR[0])
        return e;
    snprintf(buf, sizeof buf, "%s/%s", POV_FONT_DIR, base);
    return FT_New_Face(lib, buf, 0, face);
}

/*
** The character map POV-Ray 3.7 reads for a string in its default
** charset (ASCII; truetype.cpp ProcessCharMap with platform order 1, 3,
** 0): the first table of platform 1 (Macintosh), else the first of
** platform 3 (Microsoft, whatever its encoding, so also a symbol font's),
** else of platform 0 (Unicode); NULL when there is none. FreeType's own
** choice prefers Unicode: povlogo.ttf's Microsoft table is a symbol one
** where 'P' has no glyph, while its Macintosh table gives 'P' the logo
** (tests/unit/test_geom.c, POV-Ray's max_extent of "POV").
*/
static FT_CharMap pov_charmap(FT_Face face)
{
    static const int order[3] = { 1, 3, 0 };
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < face->num_charmaps; i++)
            if (face->charmaps[i]->platform_id == order[j])
                return face->charmaps[i];
    return NULL;
}

/* Glyph index of code point 'ch': ASCII through POV-Ray's table, the
** rest (iris reads strings as UTF-8) through FreeType's Unicode one. */
static FT_UInt glyph_index(FT_Face face, FT_CharMap pov, FT_CharMap uni,
                           unsigned long ch)
{
    FT_CharMap want = ch < 128 && pov ? pov : uni;
    if (!want)
        return 0;
    if (face->charmap != want && FT_Set_Charmap(face, want))
        return 0;
    return FT_Get_Char_Index(face, ch);
}

struct geom_profile *geom_text_profile(const iris_object *o, const char **why)
{
    *why = NULL;
    if (!o->u.text.font || !o->u.text.string) {
        *why = "text has no font or string";
        return NULL;
    }
    FT_Library lib;
    if (FT_Init_FreeType(&lib)) {
        *why = "FreeType cannot start";
        return NULL;
    }
    FT_Face face;
    if (open_face(lib, o->u.text.font, &face)) {
        FT_Done_FreeType(lib);
        *why = "cannot open the font file";
        return NULL;
    }
    struct geom_profile *p = geom_profile_new(256);
    struct outline_ctx c = { .p = p, .ok = p != NULL };
    c.scale = face->units_per_EM > 0 ? 1.0 / face->units_per_EM : 1.0 / 2048;
    FT_Outline_Funcs fns = { move_to, line_to, conic_to, cubic_to, 0, 0 };

    /* POV-Ray's layout (truetype.cpp): the first glyph is moved so that
    ** its left edge is at x = 0 and the pen then advances by its advance
    ** less its left side bearing; every later glyph sits at the pen plus
    ** kerning, and the pen advances by advance plus kerning; 'offset' is
    ** added after each glyph. */
    double x = 0, y = 0;
    FT_UInt prev = 0;
    FT_CharMap pov = pov_charmap(face), uni = face->charmap;
    bool first = true;
    const unsigned char *s = (const unsigned char *)o->u.text.string;
    while (*s && c.ok) {
        unsigned long ch = utf8_next(&s);
        FT_UInt gi = glyph_index(face, pov, uni, ch);
        double kern = 0;
        if (!first && prev && gi && FT_HAS_KERNING(face)) {
            FT_Vector k;
            if (!FT_Get_Kerning(face, prev, gi, FT_KERNING_UNSCALED, &k))
                kern = k.x * c.scale;
        }
        if (FT_Load_Glyph(face, gi, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING))
            continue;
        FT_GlyphSlot g = face->glyph;
        double adv = g->advance.x * c.scale;
        double lsb = g->metrics.horiBearingX * c.scale;
        double xmin = lsb;
        /* POV-Ray's glyph box: the glyf header's widened by the points
        ** (for an empty glyph the header's 0, else the points') */
        FT_BBox gb = { 0, 0, 0, 0 };
        bool have_gb = glyf_header_box(face, gi, &gb);
        if (g->format == FT_GLYPH_FORMAT_OUTLINE &&
            g->outline.n_points > 0) {
            FT_BBox box;
            FT_Outline_Get_CBox(&g->outline, &box);
            if (have_gb) {
                gb.xMin = box.xMin < gb.xMin ? box.xMin : gb.xMin;
                gb.yMin = box.yMin < gb.yMin ? box.yMin : gb.yMin;
                gb.xMax = box.xMax > gb.xMax ? box.xMax : gb.xMax;
                gb.yMax = box.yMax > gb.yMax ? box.yMax : gb.yMax;
            } else {
                gb = box;
                have_gb = true;
            }
            xmin = gb.xMin * c.scale;
        }
        if (first) {
            c.dx = -xmin;
            x = adv - lsb;
        } else {
            c.dx = x + lsb - xmin + kern;
            x += adv + kern;
        }
        c.dy = y;
        {
            /* POV-Ray's glyph box: its glyf header's, which holds every
            ** point of the outline, or a point for an empty glyph */
            double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
            if (have_gb) {
                x0 = gb.xMin * c.scale;
                x1 = gb.xMax * c.scale;
                y0 = gb.yMin * c.scale;
                y1 = gb.yMax * c.scale;
            }
            iris_vec2 glo = { c.dx + x0, c.dy + y0 };
            iris_vec2 ghi = { c.dx + x1, c.dy + y1 };
            geom_box2_add(&p->pov_lo, &p->pov_hi, &p->pov_box, glo, ghi);
        }
        if (g->format == FT_GLYPH_FORMAT_OUTLINE) {
            c.open = false;
            FT_Outline_Decompose(&g->outline, &fns, &c);
            close_contour(&c);
        }
        x += o->u.text.offset.x;
        y += o->u.text.offset.y;
        prev = gi;
        first = false;
    }
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
    if (!c.ok) {
        geom_profile_free(p);
        *why = "out of memory";
        return NULL;
    }
    geom_profile_finish(p);
    if (p->n_seg == 0) {
        geom_profile_free(p);
        *why = "the text has no visible glyphs";
        return NULL;
    }
    double th = o->u.text.thickness;
    p->h1 = fmin(0, th);
    p->h2 = fmax(0, th);
    if (p->h1 == p->h2)
        p->h2 = 1e-6; /* a zero thickness still shows the face */
    return p;
}
