# SPDX-License-Identifier: MIT
# tests/tap.sh: TAP output for shell tests, sourced by tests/**/*.sh.
#
#   . "$top_srcdir/tests/tap.sh"
#   tap_plan 3
#   tap_ok "name" command args...     # ok when the command exits 0
#   tap_is "name" "$got" "$expected"  # ok when the strings are equal
#   tap_skip_all "reason"             # the whole file is skipped
#
# A failing check prints its details as TAP comments (# ...).

tap_n=0
tap_failed=0

tap_plan() { echo "1..$1"; }

tap_skip_all() { echo "1..0 # SKIP $1"; exit 0; }

tap_result() { # tap_result STATUS NAME
    tap_n=$((tap_n + 1))
    if [ "$1" -eq 0 ]; then
        echo "ok $tap_n - $2"
    else
        echo "not ok $tap_n - $2"
        tap_failed=$((tap_failed + 1))
    fi
}

tap_result_todo() { # tap_result_todo STATUS NAME [TODO-REASON]
    # a failure with a reason is a TAP TODO (expected); one that passes
    # says the TODO can go
    tap_n=$((tap_n + 1))
    if [ "$1" -eq 0 ]; then
        echo "ok $tap_n - $2"
        [ -n "${3:-}" ] && echo "# note: passes now, drop the TODO: $3"
    elif [ -n "${3:-}" ]; then
        echo "not ok $tap_n - $2 # TODO $3"
    else
        echo "not ok $tap_n - $2"
        tap_failed=$((tap_failed + 1))
    fi
    return 0
}

tap_ok() {
    name=$1; shift
    if out=$("$@" 2>&1); then
        tap_result 0 "$name"
    else
        tap_result 1 "$name"
        printf '%s\n' "$out" | head -n 20 | sed 's/^/# /'
    fi
}

tap_is() {
    if [ "$2" = "$3" ]; then
        tap_result 0 "$1"
    else
        tap_result 1 "$1"
        echo "# got:      $2"
        echo "# expected: $3"
    fi
}

tap_comment() { echo "# $*"; }
