/* mesh2's long lists of plain vectors, `<1, -2.5, 3e2>, <...>, ...`, read
 * straight from the text on several threads (tokens.h,
 * tok_plain_vector_list). On 10^6 triangles such lists are 95% of a 43 MB
 * scene, and reading them item by item was the one part of a render left
 * on one thread.
 *
 * The text is first measured (on threads too): the run of characters a plain list is made
 * of (digits, signs, '.', 'e', commas, angle brackets and blanks: no
 * comment, identifier or directive). It is cut into pieces at '<', one per
 * thread; each piece counts its vectors, then reads them into their places,
 * every number by the lexer's own conversion (tok_number_text). Anything
 * unexpected anywhere, or a count other than n, and nothing is kept: the
 * caller reads the list item by item, which says what is wrong and where. */
#include <math.h>
#include <pthread.h>
#include <string.h>

#include "tokens.h"

#define PIECE_MIN_BYTES (1 << 20) /* below, a thread's start costs more than its share */
#define MAX_PIECES 64

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* The characters a plain list is made of: digits, blanks, . e E + - , < > */
static const unsigned char plain_chars[256] = {
    ['0'] = 1, ['1'] = 1, ['2'] = 1, ['3'] = 1, ['4'] = 1, ['5'] = 1, ['6'] = 1, ['7'] = 1, ['8'] = 1, ['9'] = 1,
    [' '] = 1, ['\t'] = 1, ['\r'] = 1, ['\n'] = 1, ['\f'] = 1, ['\v'] = 1, ['.'] = 1, ['e'] = 1, ['E'] = 1,
    ['+'] = 1, ['-'] = 1, [','] = 1, ['<'] = 1, ['>'] = 1,
};

typedef struct {
    const char *b;
    size_t from, to, size;    /* the piece [from, to) of the buffer b[0, size) */
    int first;                /* its first vector's index */
    Vec3 *out;                /* vertex_vectors, or */
    MeshFace *faces;          /* face_indices, indices below nvertices */
    int nvertices;
    int count;                /* vectors ('<') in the piece */
    long tokens;
    size_t after;             /* just after its last vector's '>' */
    int failed;
    size_t stop;              /* measuring: where the plain characters stop, or `to` */
    int newlines;             /* counting lines: '\n's in [from, to), and the last one's offset */
    size_t last_newline;
} Piece;

static size_t skip_blanks(const char *b, size_t i, size_t to)
{
    while (i < to && is_blank(b[i]))
        i++;
    return i;
}

static void *measure_piece(void *arg)
{
    Piece *pc = arg;
    size_t i = pc->from;
    while (i < pc->to && plain_chars[(unsigned char)pc->b[i]])
        i++;
    pc->stop = i;
    return NULL;
}

static void *count_newlines(void *arg)
{
    Piece *pc = arg;
    int n = 0;
    for (const char *q = pc->b + pc->from, *end = pc->b + pc->to; (q = memchr(q, '\n', (size_t)(end - q))) != NULL; q++) {
        n++;
        pc->last_newline = (size_t)(q - pc->b);
    }
    pc->newlines = n;
    return NULL;
}

static void *count_piece(void *arg)
{
    Piece *pc = arg;
    int n = 0;
    for (const char *q = pc->b + pc->from, *end = pc->b + pc->to; (q = memchr(q, '<', (size_t)(end - q))) != NULL; q++)
        n++;
    pc->count = n;
    return NULL;
}

/* The piece's vectors, each as plain_vector (expr.c) reads one: '<', three
 * numbers (each with an optional sign) separated by commas, '>', and after
 * it no operator; a comma, optional, before each. */
static void *read_piece(void *arg)
{
    Piece *pc = arg;
    const char *b = pc->b;
    size_t i = pc->from, to = pc->to;
    int k = pc->first;
    for (;;) {
        i = skip_blanks(b, i, to);
        int comma = i < to && b[i] == ',';
        if (comma)
            i = skip_blanks(b, i + 1, to);
        if (i >= to)
            break; /* a comma after the last vector is the caller's to read */
        if (b[i] != '<')
            goto fail;
        i++;
        pc->tokens += 1 + comma;
        double c[3];
        for (int j = 0; j < 3; j++) {
            i = skip_blanks(b, i, to);
            double sign = 1.0;
            if (i < to && (b[i] == '-' || b[i] == '+')) {
                sign = b[i] == '-' ? -1.0 : 1.0;
                pc->tokens++;
                i = skip_blanks(b, i + 1, to);
            }
            if (!(i < to && (is_digit(b[i]) || (b[i] == '.' && i + 1 < to && is_digit(b[i + 1])))))
                goto fail;
            size_t e;
            double v;
            if (!tok_number_text(b, i, to, &e, &v))
                goto fail;
            i = e;
            pc->tokens++;
            c[j] = sign * v;
            if (!isfinite(c[j]))
                goto fail;
            i = skip_blanks(b, i, to);
            if (!(i < to && b[i] == (j < 2 ? ',' : '>')))
                goto fail;
            i++;
            pc->tokens++;
        }
        /* an operator after it makes it part of an expression (plain_vector's
         * rule; a '/' may be a comment: the item-by-item reading decides) */
        size_t q = skip_blanks(b, i, pc->size);
        if (q < pc->size && strchr("+-*/.#", b[q]) != NULL && b[q] != '\0')
            goto fail;
        if (pc->faces) {
            MeshFace *f = &pc->faces[k];
            memset(f, 0, sizeof *f);
            for (int j = 0; j < 3; j++)
                if (!int_from_double(c[j], 0, pc->nvertices - 1, &f->v[j]))
                    goto fail;
            f->n[0] = f->n[1] = f->n[2] = -1;
            f->uv[0] = f->uv[1] = f->uv[2] = -1;
            f->texture = f->texture2 = f->texture3 = -1;
        } else {
            pc->out[k] = v3(c[0], c[1], c[2]);
        }
        k++;
        pc->after = i;
    }
    return NULL;
fail:
    pc->failed = 1;
    return NULL;
}

/* Runs fn on every piece, piece 0 here, the others on threads of their own. */
static void run_pieces(Piece *pieces, int n, void *(*fn)(void *))
{
    pthread_t tids[MAX_PIECES];
    int spawned[MAX_PIECES] = { 0 };
    for (int k = 1; k < n; k++)
        spawned[k] = pthread_create(&tids[k], NULL, fn, &pieces[k]) == 0;
    fn(&pieces[0]);
    for (int k = 1; k < n; k++) {
        if (spawned[k])
            pthread_join(tids[k], NULL);
        else
            fn(&pieces[k]);
    }
}

/* How many threads' pieces `bytes` of text make. */
static int pieces_for(size_t bytes, int threads)
{
    size_t n = bytes / PIECE_MIN_BYTES < (size_t)threads ? bytes / PIECE_MIN_BYTES : (size_t)threads;
    return n > MAX_PIECES ? MAX_PIECES : n < 1 ? 1 : (int)n;
}

/* [from, to) cut into n pieces of about equal size. */
static void cut_even(Piece *pieces, int n, const char *b, size_t from, size_t to)
{
    for (int k = 0; k < n; k++)
        pieces[k] = (Piece){ .b = b, .from = from + (to - from) * (size_t)k / (size_t)n,
                             .to = from + (to - from) * (size_t)(k + 1) / (size_t)n };
}

/* Where the run of plain characters from `start` ends: measured block by
 * block (a list is most of a big scene, but not all of the text after it),
 * each block's pieces on threads. */
static size_t plain_run_end(const char *b, size_t start, size_t size, int threads)
{
    Piece pieces[MAX_PIECES];
    for (size_t from = start; from < size;) {
        size_t block = (size_t)threads * PIECE_MIN_BYTES;
        size_t to = size - from < block ? size : from + block;
        int n = pieces_for(to - from, threads);
        cut_even(pieces, n, b, from, to);
        run_pieces(pieces, n, measure_piece);
        for (int k = 0; k < n; k++)
            if (pieces[k].stop < pieces[k].to)
                return pieces[k].stop;
        from = to;
    }
    return size;
}

int tok_plain_vector_list(Parser *p, int n, Vec3 *out, MeshFace *faces, int nvertices)
{
    /* Not where the budgets of repeated text or of time must see each
     * token (a loop, a macro's body, a deadline), nor after a token read
     * ahead, unless it is the comma the first item may have before it. */
    if (n <= 0 || p->deadline > 0.0 || (p->ungot && !tok_is_punct(&p->tok, ',')))
        return 0;
    SourceFile *f = &p->files[p->depth - 1];
    if (f->offset < f->repeated_to)
        return 0;
    const char *b = f->buf;
    int threads = p->opts->threads > 1 ? p->opts->threads : 1;
    size_t start = f->offset, end = plain_run_end(b, start, f->size, threads);
    size_t bytes = end - start;
    int npieces = pieces_for(bytes, threads);
    /* Cut at '<': a piece starts at a vector (or where the list does). */
    Piece pieces[MAX_PIECES];
    size_t cut = start;
    for (int k = 0; k < npieces; k++) {
        size_t to = k == npieces - 1 ? end : start + bytes * (size_t)(k + 1) / (size_t)npieces;
        if (to < cut)
            to = cut;
        const char *lt = to < end ? memchr(b + to, '<', end - to) : NULL;
        to = k == npieces - 1 || !lt ? end : (size_t)(lt - b);
        pieces[k] = (Piece){ .b = b, .from = cut, .to = to, .size = f->size, .out = out, .faces = faces,
                             .nvertices = nvertices };
        cut = to;
    }
    run_pieces(pieces, npieces, count_piece);
    int total = 0;
    for (int k = 0; k < npieces; k++) {
        pieces[k].first = total;
        total += pieces[k].count;
    }
    if (total != n)
        return 0; /* more or fewer: the item-by-item reading says which */
    run_pieces(pieces, npieces, read_piece);
    long tokens = 0;
    size_t after = start;
    for (int k = 0; k < npieces; k++) {
        if (pieces[k].failed)
            return 0;
        tokens += pieces[k].tokens;
        if (pieces[k].count)
            after = pieces[k].after;
    }
    /* Where the item-by-item reading would stand: after the n-th '>'. */
    int nl_pieces = pieces_for(after - start, threads);
    cut_even(pieces, nl_pieces, b, start, after);
    run_pieces(pieces, nl_pieces, count_newlines);
    int newlines = 0;
    size_t last_newline = 0;
    for (int k = 0; k < nl_pieces; k++) {
        newlines += pieces[k].newlines;
        if (pieces[k].newlines)
            last_newline = pieces[k].last_newline;
    }
    f->line += newlines;
    f->col = newlines ? (int)(after - last_newline) : f->col + (int)(after - start);
    f->offset = after;
    p->tokens_read += (unsigned)tokens;
    p->ungot = 0; /* the comma read ahead, if any, was the first item's */
    return 1;
}
