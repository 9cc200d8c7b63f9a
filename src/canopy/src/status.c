/* status.c — status code names, descriptions and per-handle error messages. */
#include "model_internal.h"

#include <stdarg.h>
#include <stdio.h>

const char *canopy_status_name(canopy_status status)
{
    switch (status) {
#define CANOPY_STATUS_NAME_(name, code, text) case name: return #name;
        CANOPY_STATUS_LIST(CANOPY_STATUS_NAME_)
#undef CANOPY_STATUS_NAME_
    default: return "CANOPY_UNKNOWN_STATUS";
    }
}

const char *canopy_status_description(canopy_status status)
{
    switch (status) {
#define CANOPY_STATUS_TEXT_(name, code, text) case name: return text;
        CANOPY_STATUS_LIST(CANOPY_STATUS_TEXT_)
#undef CANOPY_STATUS_TEXT_
    default: return "unknown status";
    }
}

static canopy_status format_va(char *buffer, size_t size, canopy_status status,
                               const char *fmt, va_list ap)
{
    if (buffer == NULL || size == 0) return status;
    int used = snprintf(buffer, size, "%s: ", canopy_status_name(status));
    if (used < 0 || (size_t)used >= size) return status;
    vsnprintf(buffer + used, size - (size_t)used, fmt, ap);
    return status;
}

canopy_status canopy_format_message(char *buffer, size_t size,
                                    canopy_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    format_va(buffer, size, status, fmt, ap);
    va_end(ap);
    return status;
}

canopy_status canopy_fail(canopy_model *model, canopy_status status,
                          const char *fmt, ...)
{
    if (model == NULL) return status;
    va_list ap;
    va_start(ap, fmt);
    format_va(model->message, sizeof model->message, status, fmt, ap);
    va_end(ap);
    return status;
}

canopy_status canopy_reject(const canopy_model *model, canopy_status status,
                            const char *fmt, ...)
{
    if (model == NULL) return status;
    /* Models are only ever allocated mutable (canopy_model_create). */
    canopy_model *m = (canopy_model *)model;
    va_list ap;
    va_start(ap, fmt);
    format_va(m->message, sizeof m->message, status, fmt, ap);
    va_end(ap);
    return status;
}

void canopy_clear_message(canopy_model *model)
{
    if (model != NULL) model->message[0] = '\0';
}

const char *canopy_model_message(const canopy_model *model)
{
    if (model == NULL) return "CANOPY_ERR_ARGUMENT: model is NULL";
    return model->message;
}
