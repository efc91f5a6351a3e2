/* lcd.c: RoBIOS LCD functions (text output and the soft-key menu). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "eyebot.h"
#include "transport.h"

#define LCD_ERROR 1

/* printf-style formatting: into `local` when it fits, else into a malloc'd string. */
static char *format_text(char *local, size_t size, const char *format, va_list ap)
{
    va_list again;
    va_copy(again, ap);
    int n = vsnprintf(local, size, format ? format : "", ap);
    char *text = local;
    if (n < 0) {
        local[0] = '\0';
    } else if ((size_t)n >= size) {
        text = malloc((size_t)n + 1);
        if (text)
            vsnprintf(text, (size_t)n + 1, format, again);
        else
            text = local; /* out of memory: print what fitted */
    }
    va_end(again);
    return text;
}

/* Sends the formatted text as the last argument of `op` (after `row`, `column` for LCD_SET_PRINTF). */
static int print_text(const char *function, uint16_t op, int row, int column, const char *format, va_list ap)
{
    char local[256];
    char *text = format_text(local, sizeof local, format, ap);
    es_value args[3], result[1];
    if (op == ES_OP_LCD_SET_PRINTF) {
        args[0] = es_int(row);
        args[1] = es_int(column);
        args[2] = es_text(text);
    } else {
        args[0] = es_text(text);
    }
    int rc = es_call(function, op, args, result);
    if (text != local)
        free(text);
    return rc ? LCD_ERROR : (int)result[0].i;
}

int LCDPrintf(const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    int rc = print_text("LCDPrintf", ES_OP_LCD_PRINTF, 0, 0, format, ap);
    va_end(ap);
    return rc;
}

int LCDSetPrintf(int row, int column, const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    int rc = print_text("LCDSetPrintf", ES_OP_LCD_SET_PRINTF, row, column, format, ap);
    va_end(ap);
    return rc;
}

int LCDClear(void)
{
    es_value result[1];
    return es_call("LCDClear", ES_OP_LCD_CLEAR, NULL, result) ? LCD_ERROR : (int)result[0].i;
}

int LCDMenu(const char *key1, const char *key2, const char *key3, const char *key4)
{
    es_value args[4] = {es_text(key1), es_text(key2), es_text(key3), es_text(key4)}, result[1];
    return es_call("LCDMenu", ES_OP_LCD_MENU, args, result) ? LCD_ERROR : (int)result[0].i;
}
