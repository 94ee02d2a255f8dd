#!/usr/bin/env bash
# The Debian package as a user gets it: CPack builds it into a scratch folder, dpkg-deb unpacks
# it, and the unpacked programs run from there with a clean environment (nothing from the build
# tree: no library path, no working folder). The validators a distribution runs check the
# desktop entry, the AppStream metadata, the MIME types and the package itself (lintian).
#   check_package.sh BUILD_DIR VERSION SOURCE_DIR
set -euo pipefail
build=$1 version=$2 source=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "check_package: $*" >&2; exit 1; }
step() { echo "check_package: $*"; }

step "cpack"
cpack --config "$build/CPackConfig.cmake" -B "$work/out" >"$work/cpack.log" 2>&1 ||
    { cat "$work/cpack.log" >&2; fail "cpack failed"; }
arch=$(dpkg --print-architecture)
deb=$work/out/valvetune_${version}_${arch}.deb
[[ -f $deb ]] || fail "no $deb (cpack: $(tail -n 3 "$work/cpack.log"))"
step "$(basename "$deb"): $(stat -c %s "$deb") bytes"

[[ $(dpkg-deb -f "$deb" Version) == "$version" ]] || fail "package version is not $version"
depends=$(dpkg-deb -f "$deb" Depends)
[[ $depends == *libqt6widgets6* && $depends == *libserialport0* ]] ||
    fail "dpkg-shlibdeps did not compute the library dependencies: '$depends'"

root=$work/root
dpkg-deb -x "$deb" "$root"
for f in usr/bin/valvetune usr/bin/valvetune-cli usr/bin/valvetune-sim \
         usr/share/applications/org.valvetune.ValveTune.desktop \
         usr/share/metainfo/org.valvetune.ValveTune.metainfo.xml \
         usr/share/mime/packages/org.valvetune.ValveTune.xml \
         usr/share/icons/hicolor/scalable/apps/org.valvetune.ValveTune.svg \
         usr/share/icons/hicolor/48x48/apps/org.valvetune.ValveTune.png \
         usr/share/icons/hicolor/128x128/apps/org.valvetune.ValveTune.png \
         usr/share/icons/hicolor/256x256/apps/org.valvetune.ValveTune.png \
         usr/share/icons/hicolor/scalable/mimetypes/application-x-valvetune-parameters.svg \
         usr/share/icons/hicolor/scalable/mimetypes/application-x-valvetune-fold-plan.svg \
         usr/share/man/man1/valvetune.1.gz usr/share/man/man1/valvetune-cli.1.gz \
         usr/share/man/man1/valvetune-sim.1.gz \
         usr/share/bash-completion/completions/valvetune-cli \
         usr/share/doc/valvetune/copyright usr/share/doc/valvetune/changelog.gz; do
    [[ -e $root/$f ]] || fail "the package lacks /$f"
done
for size in 48 128 256; do
    png=$root/usr/share/icons/hicolor/${size}x${size}/apps/org.valvetune.ValveTune.png
    [[ $(file -b "$png") == "PNG image data, $size x $size,"* ]] || fail "$png is not $size px"
done

# The unpacked programs, from a folder that is not the build tree, with a bare environment.
cd "$work"
run() { env -i PATH=/usr/bin:/bin HOME="$work" QT_QPA_PLATFORM=offscreen "$@"; }
step "valvetune-cli --version"
[[ $(run "$root/usr/bin/valvetune-cli" --version) == "valvetune-cli $version" ]] ||
    fail "valvetune-cli --version does not say $version"
step "valvetune-cli dictionary list"
families=$(run "$root/usr/bin/valvetune-cli" dictionary list)
for family in opat dma-pn-v51 dma-pb-v32 wandfluh-ed1 wandfluh-sd7; do
    grep -q "$family" <<<"$families" || fail "dictionary list lacks $family: $families"
done
step "valvetune --help"
help=$(run "$root/usr/bin/valvetune" --help) || fail "valvetune --help failed"
[[ $help == *"--simulate"* && $help == *"[FILE]"* ]] || fail "valvetune --help: $help"
[[ $(run "$root/usr/bin/valvetune" --version) == "valvetune $version" ]] ||
    fail "valvetune --version does not say $version"
[[ $(run "$root/usr/bin/valvetune-sim" --version) == "valvetune-sim $version" ]] ||
    fail "valvetune-sim --version does not say $version"
if ldd "$root"/usr/bin/* | grep -q "not found"; then
    fail "a library the programs need is not found: $(ldd "$root"/usr/bin/* | grep 'not found')"
fi

# One version everywhere: the newest AppStream release and the changelog say the package's.
metainfo=$root/usr/share/metainfo/org.valvetune.ValveTune.metainfo.xml
grep -m1 -o '<release version="[^"]*"' "$metainfo" | grep -q "\"$version\"" ||
    fail "the newest release in the metainfo is not $version"
zcat "$root/usr/share/doc/valvetune/changelog.gz" | head -n 1 | grep -q "^valvetune ($version) " ||
    fail "the changelog's first entry is not $version"

step "desktop-file-validate"
desktop-file-validate "$root/usr/share/applications/org.valvetune.ValveTune.desktop"
step "appstreamcli validate --no-net"
appstreamcli validate --no-net "$metainfo"
step "update-mime-database"
update-mime-database "$root/usr/share/mime"
for type in x-valvetune-parameters x-valvetune-fold-plan; do
    [[ -f $root/usr/share/mime/application/$type.xml ]] || fail "no MIME type application/$type"
done
step "lintian"
lintian --fail-on error,warning --display-level '>=warning' "$deb" ||
    fail "lintian found errors or unexplained warnings"
step "the package is sound"
