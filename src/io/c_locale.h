/*
 * c_locale.h - the C locale for the length of a library call.
 *
 * The library reads and writes numbers with the C library (strtod,
 * snprintf), whose decimal point is the locale's.  A host program may have
 * called setlocale(LC_ALL, "") in a locale whose decimal point is ',' (de_DE,
 * fr_FR, ...): strtod would then read "1.75" as 1 and stop.  A public entry
 * that reads or writes text therefore runs in the C locale, set for the
 * calling thread only (POSIX uselocale), so other threads of the host keep
 * theirs and two loads on two threads do not meet; the caller's locale is
 * back when the call returns, and while its diagnostic and resolver callbacks run
 * ([EMBED-LOCALE-1], spec/embedding.md).
 */
#ifndef REFRAY_C_LOCALE_H
#define REFRAY_C_LOCALE_H

#include <locale.h>

typedef struct c_locale_scope {
    locale_t c;       /* the C locale object made for this call */
    locale_t caller;  /* the thread's locale before it */
} c_locale_scope;

/* Makes the C locale the calling thread's; 0, or -1 when no locale object
 * could be made (out of memory), with nothing changed. */
int c_locale_enter(c_locale_scope *s);

/* Gives the thread its caller's locale back and frees the C one. */
void c_locale_leave(c_locale_scope *s);

/* Around a callback of the caller: its locale while it runs, then ours. */
void c_locale_to_caller(const c_locale_scope *s);
void c_locale_from_caller(const c_locale_scope *s);

#endif
