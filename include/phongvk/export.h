// export.h — PHONGVK_API marks what libphongvk.so exports: the public API and nothing else (the
// library is built with hidden visibility, so internals cannot be called from outside by mistake).
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define PHONGVK_API __attribute__((visibility("default")))
#else
#define PHONGVK_API
#endif
