/* SPDX-License-Identifier: MIT */
/*
** lex.c: the raw scanner: one token at a byte offset of a file in memory.
**
** It records only the offset and length of each token (line and column
** come from diag.c's line map when a message needs them) and knows
** nothing of directives or symbols: input.c builds on it. Comments nest,
** as in POV-Ray. A UTF-8 byte order mark at the start of a file is
** skipped; NUL bytes and other control characters are errors.
*/
#include "config.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "pp.h"

static const char *const kw_names[T_NUM_TOKENS] = {
#define TOK(name, word) [T_##name] = word,
#define ALIAS(name, word)
#include "tokens.def"
#undef TOK
#undef ALIAS
};

struct kw_alias { int kind; const char *word; };
static const struct kw_alias kw_aliases[] = {
#define TOK(name, word)
#define ALIAS(name, word) { T_##name, word },
#include "tokens.def"
#undef TOK
#undef ALIAS
};

static unsigned hash_word(const char *s, size_t n)
{
    unsigned h = 2166136261u;
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h;
}

static void kw_insert(pp_state *ps, const char *word, int kind)
{
    unsigned h = hash_word(word, strlen(word)) & ps->kw_mask;
    while (ps->kw_hash[h])
        h = (h + 1) & ps->kw_mask;
    ps->kw_hash[h] = kind;
    ps->kw_name[h] = word;
}

void lex_init_keywords(pp_state *ps)
{
    unsigned size = 2048;
    ps->kw_mask = size - 1;
    ps->kw_hash = pp_salloc(ps, size * sizeof *ps->kw_hash);
    ps->kw_name = pp_salloc(ps, size * sizeof *ps->kw_name);
    for (int k = T_KW_FIRST + 1; k < T_NUM_TOKENS; k++)
        kw_insert(ps, kw_names[k], k);
    for (size_t i = 0; i < sizeof kw_aliases / sizeof kw_aliases[0]; i++)
        kw_insert(ps, kw_aliases[i].word, kw_aliases[i].kind);
}

const char *lex_keyword_name(int kind)
{
    if (kind > T_KW_FIRST && kind < T_NUM_TOKENS)
        return kw_names[kind];
    return NULL;
}

static int kw_find(pp_state *ps, const char *s, size_t n)
{
    unsigned h = hash_word(s, n) & ps->kw_mask;
    while (ps->kw_hash[h]) {
        const char *w = ps->kw_name[h];
        if (strncmp(w, s, n) == 0 && w[n] == 0)
            return ps->kw_hash[h];
        h = (h + 1) & ps->kw_mask;
    }
    return 0;
}

/* Skips white space and comments from 'p'; returns the new offset. */
static uint32_t skip_space(pp_state *ps, uint32_t f, uint32_t p)
{
    const char *s = ps->files[f].text;
    uint32_t n = (uint32_t)ps->files[f].len;
    for (;;) {
        while (p < n && (s[p] == ' ' || s[p] == '\t' || s[p] == '\n' ||
                         s[p] == '\r' || s[p] == '\f' || s[p] == '\v' ||
                         s[p] == 26 /* DOS EOF marker */))
            p++;
        if (p + 1 < n && s[p] == '/' && s[p + 1] == '/') {
            while (p < n && s[p] != '\n')
                p++;
            continue;
        }
        if (p + 1 < n && s[p] == '/' && s[p + 1] == '*') {
            uint32_t start = p;
            int depth = 0;
            while (p < n) {
                if (p + 1 < n && s[p] == '/' && s[p + 1] == '*') {
                    depth++;
                    p += 2;
                } else if (p + 1 < n && s[p] == '*' && s[p + 1] == '/') {
                    p += 2;
                    if (--depth == 0)
                        break;
                } else {
                    p++;
                }
            }
            if (depth > 0)
                pp_error_at(ps, f, start, 2, "unterminated comment");
            continue;
        }
        return p;
    }
}

/* Decodes a string literal starting at the '"' at 'p'. */
static uint32_t scan_string(pp_state *ps, uint32_t f, uint32_t p,
                            pp_token *t)
{
    const char *s = ps->files[f].text;
    uint32_t n = (uint32_t)ps->files[f].len;
    uint32_t start = p++;
    uint32_t q = p;
    /* POV-Ray strings may span lines */
    while (q < n && s[q] != '"') {
        if (s[q] == '\\' && q + 1 < n)
            q++;
        q++;
    }
    if (q >= n || s[q] != '"')
        pp_error_at(ps, f, start, 1, "unterminated string");
    t->kind = T_STRING;
    t->len = q + 1 - start;
    if (ps->lex_peek) {
        /* a look-ahead only needs the token's kind and extent */
        t->str = "";
        return q + 1;
    }
    char *out = pp_salloc(ps, q - p + 1);
    size_t k = 0;
    while (p < q) {
        char c = s[p++];
        if (c == '\\' && p < q) {
            char e = s[p++];
            switch (e) {
            case 'n': c = '\n'; break;
            case 't': c = '\t'; break;
            case 'r': c = '\r'; break;
            case 'a': c = '\a'; break;
            case 'b': c = '\b'; break;
            case 'f': c = '\f'; break;
            case 'v': c = '\v'; break;
            case '0': c = 0; break;
            case '\\': case '"': case '\'': c = e; break;
            case 'u': {
                /* \uXXXX: POV-Ray's String_To_UCS2 reads 4 hex digits as
                ** one UCS-2 character; iris keeps one byte below 256
                ** (Latin-1, so strlen and substr count as POV-Ray does;
                ** text reads a lone byte as Latin-1) and UTF-8 above.
                ** Without 4 hex digits it stays as written, like other
                ** unknown escapes (a Windows path "C:\users\..."). */
                char hex[5] = { 0, 0, 0, 0, 0 };
                int nh = 0;
                while (nh < 4 && p + (uint32_t)nh < q &&
                       isxdigit((unsigned char)s[p + (uint32_t)nh])) {
                    hex[nh] = s[p + (uint32_t)nh];
                    nh++;
                }
                if (nh < 4) {
                    out[k++] = '\\';
                    c = e;
                    break;
                }
                p += 4;
                unsigned long u = strtoul(hex, NULL, 16);
                if (u == 0) {
                    c = 0;
                } else if (u < 0x100) {
                    c = (char)u;
                } else {
                    if (u < 0x800) {
                        out[k++] = (char)(0xc0 | (u >> 6));
                    } else {
                        out[k++] = (char)(0xe0 | (u >> 12));
                        out[k++] = (char)(0x80 | ((u >> 6) & 0x3f));
                    }
                    c = (char)(0x80 | (u & 0x3f));
                }
                break;
            }
            default:
                /* POV-Ray keeps unknown escapes (Windows paths) as is. */
                out[k++] = '\\';
                c = e;
                break;
            }
            if (c == 0) /* a string cannot hold NUL: end it there */
                break;
        }
        out[k++] = c;
    }
    out[k] = 0;
    t->kind = T_STRING;
    t->str = out;
    t->len = q + 1 - start;
    return q + 1;
}

uint32_t lex_scan(pp_state *ps, uint32_t f, uint32_t pos, pp_token *t)
{
    const char *s = ps->files[f].text;
    uint32_t n = (uint32_t)ps->files[f].len;
    if (pos == 0 && n >= 3 && (unsigned char)s[0] == 0xEF &&
        (unsigned char)s[1] == 0xBB && (unsigned char)s[2] == 0xBF)
        pos = 3;
    uint32_t p = skip_space(ps, f, pos);
    /* Every field cleared one by one: a memset of the whole token was a
    ** sixth of the parse time ('rep stos' for each token scanned). */
    t->num = 0;
    t->str = NULL;
    t->sym = NULL;
    t->val.kind = V_NONE;
    t->val.dim = 0;
    for (int i = 0; i < 5; i++)
        t->val.v[i] = 0;
    t->val.u.ptr = NULL;
    t->kind = T_EOF;
    t->file = f;
    t->off = p;
    t->len = 1;
    if (p >= n) {
        t->kind = T_EOF;
        t->len = 0;
        return p;
    }
    unsigned char c = (unsigned char)s[p];
    if (isalpha(c) || c == '_') {
        uint32_t q = p;
        while (q < n && (isalnum((unsigned char)s[q]) || s[q] == '_'))
            q++;
        t->len = q - p;
        int kw = kw_find(ps, s + p, q - p);
        /* 'tau' is a word of POV-Ray 3.8: 3.7 scenes declare their own
        ** (#declare tau = ...; aelnonym's camlight.inc) */
        if (kw == T_TAU && !(ps->version_set && ps->version >= 3.8))
            kw = 0;
        t->kind = kw ? kw : T_IDENT;
        return q;
    }
    if (isdigit(c) || (c == '.' && p + 1 < n && isdigit((unsigned char)s[p + 1]))) {
        uint32_t q = p;
        while (q < n && isdigit((unsigned char)s[q]))
            q++;
        if (q < n && s[q] == '.') {
            q++;
            while (q < n && isdigit((unsigned char)s[q]))
                q++;
        }
        if (q < n && (s[q] == 'e' || s[q] == 'E')) {
            uint32_t r = q + 1;
            if (r < n && (s[r] == '+' || s[r] == '-'))
                r++;
            if (r < n && isdigit((unsigned char)s[r])) {
                while (r < n && isdigit((unsigned char)s[r]))
                    r++;
                q = r;
            }
        }
        char buf[64];
        size_t len = q - p;
        if (len >= sizeof buf)
            len = sizeof buf - 1;
        memcpy(buf, s + p, len);
        buf[len] = 0;
        t->kind = T_NUMBER;
        t->num = strtod(buf, NULL);
        t->len = q - p;
        return q;
    }
    if (c == '"')
        return scan_string(ps, f, p, t);
    int kind = T_OTHER;
    uint32_t len = 1;
    char d = p + 1 < n ? s[p + 1] : 0;
    switch (c) {
    case '{': kind = T_LBRACE; break;
    case '}': kind = T_RBRACE; break;
    case '(': kind = T_LPAREN; break;
    case ')': kind = T_RPAREN; break;
    case '[': kind = T_LBRACKET; break;
    case ']': kind = T_RBRACKET; break;
    case '<': kind = T_LT; if (d == '=') { kind = T_LE; len = 2; } break;
    case '>': kind = T_GT; if (d == '=') { kind = T_GE; len = 2; } break;
    case '=': kind = T_EQUALS; break;
    case '!': kind = T_BANG; if (d == '=') { kind = T_NE; len = 2; } break;
    case ',': kind = T_COMMA; break;
    case ';': kind = T_SEMI; break;
    case '+': kind = T_PLUS; break;
    case '-': kind = T_MINUS; break;
    case '*': kind = T_STAR; break;
    case '/': kind = T_SLASH; break;
    case '#': kind = T_HASH; break;
    case '?': kind = T_QUESTION; break;
    case ':': kind = T_COLON; break;
    case '&': kind = T_AMP; break;
    case '|': kind = T_BAR; break;
    case '.': kind = T_DOT; break;
    default:
        if (c == 0)
            pp_error_at(ps, f, p, 1, "NUL byte in the source");
        if (c < 32 || c >= 127)
            pp_error_at(ps, f, p, 1, "illegal character (byte 0x%02x)", c);
        pp_error_at(ps, f, p, 1, "illegal character '%c'", c);
    }
    t->kind = kind;
    t->len = len;
    return p + len;
}

uint32_t lex_peek(pp_state *ps, uint32_t f, uint32_t pos, pp_token *t)
{
    ps->lex_peek++;
    uint32_t r = lex_scan(ps, f, pos, t);
    ps->lex_peek--;
    return r;
}
