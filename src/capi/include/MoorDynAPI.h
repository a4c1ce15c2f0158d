/* librodyn: MoorDyn v2's C API served by rodyn (docs/capi.md). The names, types and
 * codes are MoorDyn v2.7's (its source/MoorDynAPI.h), so that a host program written
 * for MoorDyn compiles against these headers unchanged. */
#ifndef __MOORDYNAPI_H__
#define __MOORDYNAPI_H__

#define DECLDIR
#if defined(__GNUC__)
#define DEPRECATED __attribute__((__deprecated__))
#else
#define DEPRECATED
#endif

#ifndef __FUNC_NAME__
#define __FUNC_NAME__ __func__
#endif
#ifndef __PRETTY_FUNC_NAME__
#define __PRETTY_FUNC_NAME__ __PRETTY_FUNCTION__
#endif
#ifndef XSTR
#define XSTR(s) STR(s)
#endif
#ifndef STR
#define STR(s) #s
#endif

/* log levels */
#define MOORDYN_ERR_LEVEL 3
#define MOORDYN_WRN_LEVEL 2
#define MOORDYN_MSG_LEVEL 1
#define MOORDYN_DBG_LEVEL 0
#define MOORDYN_NO_OUTPUT 4096

/* the codes every function returns */
#define MOORDYN_SUCCESS 0
#define MOORDYN_INVALID_INPUT_FILE -1
#define MOORDYN_INVALID_OUTPUT_FILE -2
#define MOORDYN_INVALID_INPUT -3
#define MOORDYN_NAN_ERROR -4
#define MOORDYN_MEM_ERROR -5
#define MOORDYN_INVALID_VALUE -6
#define MOORDYN_NON_IMPLEMENTED -7
#define MOORDYN_UNHANDLED_ERROR -255

#endif
