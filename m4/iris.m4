dnl SPDX-License-Identifier: MIT
dnl m4/iris.m4: the project's own small autoconf macros.

dnl IRIS_CHECK_CFLAG(FLAG, ACTION-IF-ACCEPTED)
dnl Runs ACTION when the C compiler accepts FLAG without a warning.
AC_DEFUN([IRIS_CHECK_CFLAG], [
  AS_VAR_PUSHDEF([cache], [iris_cv_cflag_$1])
  AC_CACHE_CHECK([whether $CC accepts $1], [cache], [
    iris_save_CFLAGS="$CFLAGS"
    CFLAGS="$CFLAGS -Werror $1"
    AC_LANG_PUSH([C])
    AC_COMPILE_IFELSE([AC_LANG_PROGRAM([], [])],
      [AS_VAR_SET([cache], [yes])], [AS_VAR_SET([cache], [no])])
    AC_LANG_POP([C])
    CFLAGS="$iris_save_CFLAGS"])
  AS_VAR_IF([cache], [yes], [$2])
  AS_VAR_POPDEF([cache])
])

dnl IRIS_CHECK_CXXFLAG(FLAG, ACTION-IF-ACCEPTED)
AC_DEFUN([IRIS_CHECK_CXXFLAG], [
  AS_VAR_PUSHDEF([cache], [iris_cv_cxxflag_$1])
  AC_CACHE_CHECK([whether $CXX accepts $1], [cache], [
    iris_save_CXXFLAGS="$CXXFLAGS"
    CXXFLAGS="$CXXFLAGS -Werror $1"
    AC_LANG_PUSH([C++])
    AC_COMPILE_IFELSE([AC_LANG_PROGRAM([], [])],
      [AS_VAR_SET([cache], [yes])], [AS_VAR_SET([cache], [no])])
    AC_LANG_POP([C++])
    CXXFLAGS="$iris_save_CXXFLAGS"])
  AS_VAR_IF([cache], [yes], [$2])
  AS_VAR_POPDEF([cache])
])

dnl AX_PTHREAD_LITE: sets PTHREAD_CFLAGS and PTHREAD_LIBS for GCC and
dnl Clang on GNU/Linux (-pthread), failing with the package to install.
AC_DEFUN([AX_PTHREAD_LITE], [
  AC_MSG_CHECKING([whether -pthread links pthread_create])
  iris_save_CFLAGS="$CFLAGS"; iris_save_LIBS="$LIBS"
  CFLAGS="$CFLAGS -pthread"; LIBS="$LIBS -pthread"
  AC_LINK_IFELSE([AC_LANG_PROGRAM([[#include <pthread.h>
static void *f(void *a) { return a; }]],
                   [[pthread_t t; return pthread_create(&t, 0, f, 0);]])],
    [AC_MSG_RESULT([yes]); PTHREAD_CFLAGS="-pthread"; PTHREAD_LIBS="-pthread"],
    [AC_MSG_RESULT([no]); AC_MSG_ERROR([POSIX threads are required (Debian: libc6-dev)])])
  CFLAGS="$iris_save_CFLAGS"; LIBS="$iris_save_LIBS"
  AC_SUBST([PTHREAD_CFLAGS])
  AC_SUBST([PTHREAD_LIBS])
])
