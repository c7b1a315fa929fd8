/*
** font.h - the bitmap font text is drawn with: 5 x 9 cells, capitals
** and digits 7 rows high on a baseline at row 6, descenders in rows 7
** and 8.  Covers printable ASCII and a few symbols for labels
** (σ ε μ ν ρ Δ ± × ° ·).
*/
#ifndef mvmpm_font_h
#define mvmpm_font_h

#define FONT_W 5
#define FONT_H 9
#define FONT_BASE 6   /* the baseline row */

/* the glyph of code point cp as up to 9 rows of 5 characters separated
** by single spaces, '#' for ink and '.' for none (rows left out are
** blank); NULL if the font has no such glyph */
const char *font_glyph(unsigned long cp);

/* decode one UTF-8 character at *s, advancing *s (an invalid byte
** reads as itself, so nothing is ever skipped silently) */
unsigned long font_next(const char **s);

#endif
