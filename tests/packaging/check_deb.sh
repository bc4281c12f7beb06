#!/usr/bin/env bash
# Builds the Debian package into a temporary folder, extracts it with dpkg-deb and checks it:
# the file list, the programs' --version, a render of the installed reference room, and the
# desktop entry and metainfo validators when they are installed.
# Usage: check_deb.sh CPACK BUILD_DIR VERSION
set -euo pipefail

readonly cpack="$1" build_dir="$2" version="$3"
tmp="$(mktemp -d)"
trap 'rm -rf "${tmp}"' EXIT

fail() {
    printf 'check_deb: FAIL: %s\n' "$*" >&2
    exit 1
}

echo "== cpack"
(cd "${build_dir}" && "${cpack}" -G DEB -B "${tmp}/out" >"${tmp}/cpack.log" 2>&1) ||
    { cat "${tmp}/cpack.log" >&2; fail "cpack failed"; }
deb="${tmp}/out/raystudio_${version}_$(dpkg --print-architecture).deb"
[[ -f "${deb}" ]] || fail "no package named $(basename "${deb}") in: $(ls "${tmp}/out")"

echo "== control"
dpkg-deb -f "${deb}" Package Version Depends
depends="$(dpkg-deb -f "${deb}" Depends)"
[[ "$(dpkg-deb -f "${deb}" Version)" == "${version}" ]] || fail "package version is not ${version}"
for lib in libc6 libqt6widgets6 libtbb12 libembree3-3; do
    [[ "${depends}" == *"${lib}"* ]] || fail "Depends lacks ${lib} (dpkg-shlibdeps not run?)"
done

echo "== file list"
root="${tmp}/root"
dpkg-deb -x "${deb}" "${root}"
expected=(
    usr/bin/raystudio
    usr/bin/raystudio-cli
    usr/share/raystudio/scenes/reference-room.scene.json
    usr/share/raystudio/scenes/mesh.scene.json
    usr/share/raystudio/scenes/meshes/torus.obj
    usr/share/applications/raystudio.desktop
    usr/share/icons/hicolor/scalable/apps/raystudio.svg
    usr/share/icons/hicolor/16x16/apps/raystudio.png
    usr/share/icons/hicolor/48x48/apps/raystudio.png
    usr/share/icons/hicolor/256x256/apps/raystudio.png
    usr/share/mime/packages/raystudio-scene.xml
    usr/share/metainfo/org.raystudio.RayStudio.metainfo.xml
    usr/share/man/man1/raystudio.1.gz
    usr/share/man/man1/raystudio-cli.1.gz
    usr/share/doc/raystudio/copyright
    usr/share/doc/raystudio/changelog.gz
)
for path in "${expected[@]}"; do
    [[ -f "${root}/${path}" ]] || fail "missing from the package: /${path}"
done
[[ -x "${root}/usr/bin/raystudio" && -x "${root}/usr/bin/raystudio-cli" ]] ||
    fail "the programs are not executable"
if (cd "${root}" && find . -path ./usr -prune -o -print | grep -v '^\.$'); then
    fail "files outside /usr (listed above)"
fi
file "${root}/usr/bin/raystudio-cli" | grep -q ', stripped' || fail "raystudio-cli is not stripped"
bad_perm="$(find "${root}" \( -type d ! -perm 0755 \) -o \( -type f ! -perm 0644 ! -perm 0755 \))"
[[ -z "${bad_perm}" ]] || fail "unusual permissions: ${bad_perm}"

echo "== programs"
out="$("${root}/usr/bin/raystudio-cli" --version)"
echo "${out}"
[[ "${out}" == "raystudio-cli ${version}"* ]] || fail "raystudio-cli --version printed '${out}'"
out="$("${root}/usr/bin/raystudio" --version)"
echo "${out}"
[[ "${out}" == "raystudio ${version}"* ]] || fail "raystudio --version printed '${out}'"
help="$(env -u DISPLAY -u WAYLAND_DISPLAY "${root}/usr/bin/raystudio" --help)" ||
    fail "raystudio --help failed without a display"
[[ "${help}" == *"--print-opened-scene"* ]] || fail "raystudio --help printed '${help}'"
scenes="${root}/usr/share/raystudio/scenes"
# The installed designer, started with no argument from an unrelated folder, opens the
# installed reference room (offscreen: no display needed).
opened="$(cd "${tmp}" && QT_QPA_PLATFORM=offscreen "${root}/usr/bin/raystudio" --print-opened-scene)" ||
    fail "the installed designer opened no scene"
echo "designer opened ${opened}"
[[ "${opened}" == "$(realpath "${scenes}/reference-room.scene.json")" ]] ||
    fail "the installed designer opened '${opened}', not the installed reference room"
"${root}/usr/bin/raystudio-cli" validate "${scenes}/mesh.scene.json"
"${root}/usr/bin/raystudio-cli" render "${scenes}/reference-room.scene.json" \
    -o "${tmp}/room.png" --width 160 --height 90 --threads 1
[[ -s "${tmp}/room.png" ]] || fail "the installed reference room did not render"

echo "== desktop entry, MIME type, metainfo"
if command -v desktop-file-validate >/dev/null; then
    desktop-file-validate "${root}/usr/share/applications/raystudio.desktop"
else
    echo "desktop-file-validate not installed (desktop-file-utils): skipped"
fi
if command -v appstreamcli >/dev/null; then
    appstreamcli validate --no-net "${root}/usr/share/metainfo/org.raystudio.RayStudio.metainfo.xml"
else
    echo "appstreamcli not installed (appstream): skipped"
fi
if command -v update-mime-database >/dev/null; then
    mkdir -p "${tmp}/mime/packages"
    cp "${root}/usr/share/mime/packages/raystudio-scene.xml" "${tmp}/mime/packages/"
    XDG_DATA_HOME="${tmp}" update-mime-database "${tmp}/mime"
    grep -q 'application/x-raystudio-scene:\*\.scene\.json' "${tmp}/mime/globs2" ||
        fail "the MIME database has no *.scene.json glob"
    grep -q 'raystudio-scene' "${tmp}/mime/magic" || fail "the MIME database has no magic"
else
    echo "update-mime-database not installed (shared-mime-info): skipped"
fi
grep -q '^MimeType=application/x-raystudio-scene;' "${root}/usr/share/applications/raystudio.desktop" ||
    fail "the desktop entry does not open scene files"
echo "check_deb: OK"
