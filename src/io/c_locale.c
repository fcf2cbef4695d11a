/*
 * c_locale.c - the C locale for the length of a library call (c_locale.h).
 */
#include "io/c_locale.h"

int c_locale_enter(c_locale_scope *s)
{
    s->c = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    if (s->c == (locale_t)0)
        return -1;
    s->caller = uselocale(s->c);
    return 0;
}

void c_locale_leave(c_locale_scope *s)
{
    uselocale(s->caller);
    freelocale(s->c);
}

void c_locale_to_caller(const c_locale_scope *s)
{
    uselocale(s->caller);
}

void c_locale_from_caller(const c_locale_scope *s)
{
    uselocale(s->c);
}
