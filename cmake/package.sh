#!/bin/sh
# SPDX-License-Identifier: MIT
# package.sh OUTDIR PREFIX LIBDIR INCLUDEDIR VERSION SONAME SIZEOF_VOID_P -
# the CMake package `make install` puts in LIBDIR/cmake/collide2d, as
# `cmake --install` does (CMakeLists.txt), without CMake:
#   collide2dConfig.cmake         cmake/collide2dConfig.cmake.in, with
#                                 @PACKAGE_INIT@ expanded as
#                                 configure_package_config_file() does
#   collide2dConfigVersion.cmake  cmake/collide2dConfigVersion.cmake.in
#                                 (SameMajorVersion)
#   collide2dTargets.cmake        cmake/collide2dTargets.cmake.in
# Directories under PREFIX are named relative to the package's own
# directory, so a moved prefix (a DESTDIR staging tree) works.
# SIZEOF_VOID_P may be empty (no 32/64-bit check).  Paths may hold spaces.
set -eu
[ $# -eq 7 ] || { echo "usage: package.sh OUTDIR PREFIX LIBDIR INCLUDEDIR VERSION SONAME SIZEOF_VOID_P" >&2; exit 2; }
out=$1 prefix=${2%/} libdir=$3 includedir=$4 version=$5 soname=$6 voidp=$7
here=$(dirname "$0")
cmakedir=$libdir/cmake/collide2d

# up: the path from the package directory to PREFIX ("../../../" for
# lib/cmake/collide2d), empty when the package directory is not under PREFIX.
up=
case $cmakedir in
"$prefix"/*)
    r=${cmakedir#"$prefix"/}
    while [ -n "$r" ]; do
        up=$up../
        case $r in */*) r=${r#*/} ;; *) r= ;; esac
    done
    ;;
esac
# under DIR: ${_IMPORT_PREFIX}/... when DIR lies under PREFIX, else DIR.
under() {
    case $1 in
    "$prefix"/*) printf '%s' "\${_IMPORT_PREFIX}/${1#"$prefix"/}" ;;
    *) printf '%s' "$1" ;;
    esac
}
# esc VALUE: VALUE as a sed replacement text (| is the delimiter).
esc() { printf '%s' "$1" | sed 's/[\\|&]/\\&/g'; }

if [ -n "$up" ]; then
    import_prefix="get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_DIR}/$up\" ABSOLUTE)"
    package_prefix="get_filename_component(PACKAGE_PREFIX_DIR \"\${CMAKE_CURRENT_LIST_DIR}/$up\" ABSOLUTE)"
else
    import_prefix="set(_IMPORT_PREFIX \"$prefix\")"
    package_prefix="set(PACKAGE_PREFIX_DIR \"$prefix\")"
fi

mkdir -p "$out"
sed -e "s|@C2D_IMPORT_PREFIX@|$(esc "$import_prefix")|" \
    -e "s|@C2D_INCLUDEDIR@|$(esc "$(under "$includedir")")|g" \
    -e "s|@C2D_LIBDIR@|$(esc "$(under "$libdir")")|g" \
    -e "s|@C2D_VERSION@|$(esc "$version")|g" -e "s|@C2D_SONAME@|$(esc "$soname")|g" \
    "$here/collide2dTargets.cmake.in" >"$out/collide2dTargets.cmake.tmp"
sed -e "s|@C2D_VERSION@|$(esc "$version")|g" -e "s|@C2D_SIZEOF_VOID_P@|$(esc "$voidp")|g" \
    "$here/collide2dConfigVersion.cmake.in" >"$out/collide2dConfigVersion.cmake.tmp"
# The Makefile builds every variant, static and shared.
awk -v pp="$package_prefix" '
$0 == "@PACKAGE_INIT@" {
    print ""
    print "####### Expanded from @PACKAGE_INIT@ by configure_package_config_file() #######"
    print "####### Any changes to this file will be overwritten by the next CMake run ####"
    print "####### The input file was collide2dConfig.cmake.in                            ########"
    print ""
    print pp
    print ""
    print "macro(set_and_check _var _file)"
    print "  set(${_var} \"${_file}\")"
    print "  if(NOT EXISTS \"${_file}\")"
    print "    message(FATAL_ERROR \"File or directory ${_file} referenced by variable ${_var} does not exist !\")"
    print "  endif()"
    print "endmacro()"
    print ""
    print "macro(check_required_components _NAME)"
    print "  foreach(comp ${${_NAME}_FIND_COMPONENTS})"
    print "    if(NOT ${_NAME}_${comp}_FOUND)"
    print "      if(${_NAME}_FIND_REQUIRED_${comp})"
    print "        set(${_NAME}_FOUND FALSE)"
    print "      endif()"
    print "    endif()"
    print "  endforeach()"
    print "endmacro()"
    print ""
    print "####################################################################################"
    next
}
{ print }' "$here/collide2dConfig.cmake.in" |
    sed -e 's|@C2D_NO_DOUBLE@|OFF|' -e 's|@C2D_NO_FLOAT@|OFF|' -e 's|@C2D_NO_FIXED@|OFF|' \
        -e 's|@BUILD_SHARED_LIBS@|ON|' >"$out/collide2dConfig.cmake.tmp"
for f in collide2dConfig.cmake collide2dConfigVersion.cmake collide2dTargets.cmake; do
    if grep -n '@[A-Z_]*@' "$out/$f.tmp" | grep -v 'PACKAGE_INIT' >&2; then
        echo "package.sh: $f: placeholder left" >&2
        exit 1
    fi
    if cmp -s "$out/$f.tmp" "$out/$f"; then rm -f "$out/$f.tmp"; else mv "$out/$f.tmp" "$out/$f"; fi
done
