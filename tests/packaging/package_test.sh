#!/usr/bin/env bash
# The appliance package, end to end (docs/appliance.md): builds the .deb from this build folder
# with CPack, checks its files and control fields, runs lintian, installs it into a throwaway
# root, creates its user and folders there as the maintainer scripts would, runs that root's
# `steerseg --self-test` offscreen, and verifies the unit with systemd-analyze.
#   package_test.sh BUILD_DIR
# Installing: `dpkg -x`, not `dpkg --root -i`: the latter needs a root with its own dpkg database
# and every dependency installed, and runs the maintainer scripts chrooted into it. Their two
# offline steps (systemd-sysusers, systemd-tmpfiles) run here with --root instead; the steps
# that talk to running daemons (udevadm, systemctl) are guarded in the scripts and checked for
# syntax only.
set -euo pipefail

build=${1:?build folder}
work=$(mktemp -d "${TMPDIR:-/tmp}/steerseg-package.XXXXXX")
trap 'rm -rf "$work"' EXIT
chmod 755 "$work" # the service user's self-test below walks into it
fails=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
step() { echo "== $*"; }

step "cpack"
cpack --config "$build/CPackConfig.cmake" -B "$work/out" >"$work/cpack.log" 2>&1 || {
    cat "$work/cpack.log"
    exit 1
}
debs=("$work"/out/*.deb)
[[ ${#debs[@]} -eq 1 && -f ${debs[0]} ]] || { echo "FAIL: expected one .deb, got: ${debs[*]}"; exit 1; }
deb=${debs[0]}
echo "$(basename "$deb"): $(stat -c %s "$deb") bytes"

step "contents (dpkg-deb -c)"
dpkg-deb -c "$deb" >"$work/contents"
for path in ./usr/bin/steerseg ./etc/steerseg/steerseg.toml ./usr/share/steerseg/steerseg.toml \
    ./lib/systemd/system/steerseg-kiosk.service ./usr/lib/sysusers.d/steerseg.conf \
    ./usr/lib/tmpfiles.d/steerseg.conf ./lib/udev/rules.d/70-steerseg.rules \
    ./usr/lib/steerseg/is-radial-controller ./usr/share/doc/steerseg/copyright \
    ./usr/share/doc/steerseg/changelog.Debian.gz ./usr/share/man/man1/steerseg.1.gz \
    ./usr/share/lintian/overrides/steerseg; do
    grep -q " $path\$" "$work/contents" || fail "$path is not in the package"
done
grep -q '^-rwxr-xr-x root/root .* ./usr/bin/steerseg$' "$work/contents" ||
    fail "/usr/bin/steerseg is not root-owned 0755"
# Nothing outside the Debian paths the package means (a stray /usr/local, a build path):
# each entry lies in one of these folders or is a parent of one.
allowed=(./etc/steerseg/ ./lib/systemd/system/ ./lib/udev/rules.d/ ./usr/bin/ ./usr/lib/steerseg/
    ./usr/lib/sysusers.d/ ./usr/lib/tmpfiles.d/ ./usr/share/doc/steerseg/ ./usr/share/man/man1/
    ./usr/share/steerseg/ ./usr/share/lintian/overrides/)
while read -r path; do
    ok=0
    for dir in "${allowed[@]}"; do
        [[ $path == "$dir"?* || $dir == "$path"* ]] && ok=1
    done
    [[ $ok -eq 1 ]] || fail "unexpected path in the package: $path"
done < <(awk '{ print $6 }' "$work/contents")

step "control (dpkg-deb -I)"
dpkg-deb -e "$deb" "$work/control"
[[ $(cat "$work/control/conffiles") == "/etc/steerseg/steerseg.toml" ]] ||
    fail "conffiles: $(cat "$work/control/conffiles")"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
# From dpkg-shlibdeps (the libraries the binary links), and the font it cannot see.
for lib in libc6 libstdc++6 libegl1 libgles2 libsystemd0 libgbm1 fonts-dejavu-core; do
    [[ ",$depends" == *[\ ,]"$lib"[\ ,\(]* || ",$depends," == *[\ ,]"$lib," ]] ||
        fail "Depends lacks $lib"
done
for script in postinst prerm postrm; do
    [[ -x $work/control/$script ]] || fail "$script is missing or not executable"
    sh -n "$work/control/$script" || fail "$script: syntax"
done

step "lintian"
# Tags are errors and warnings; info tags are listed, not failed. Overrides (with reasons):
# packaging/lintian-overrides, shipped in the package where lintian reads them.
lintian_status=0
lintian --fail-on error,warning --info "$deb" >"$work/lintian.log" 2>&1 || lintian_status=$?
grep -v '^running with root privileges' "$work/lintian.log" || true
[[ $lintian_status -eq 0 ]] || fail "lintian reported errors or warnings (above)"

step "install into a throwaway root (dpkg -x)"
root="$work/root"
dpkg -x "$deb" "$root"
systemd-sysusers --root="$root" 2>&1
grep -q '^steerseg:x:[0-9]*:[0-9]*:.*:/var/lib/steerseg:' "$root/etc/passwd" ||
    fail "sysusers made no steerseg user"
for group in video render input gpio; do
    grep -Eq "^$group:x:[0-9]+:(.*,)?steerseg(,|\$)" "$root/etc/group" ||
        fail "steerseg is not in group $group"
done
# Only root may hand the folders to the steerseg user: elsewhere tmpfiles creates them, fails
# the chown (status 73, "cannot create") and they stay this user's.
tmpfiles_status=0
systemd-tmpfiles --root="$root" --create 2>&1 || tmpfiles_status=$?
if [[ $(id -u) -eq 0 ]]; then
    owner=$(awk -F: '$1 == "steerseg" { print $3 ":" $4 }' "$root/etc/passwd")
    [[ $tmpfiles_status -eq 0 ]] || fail "systemd-tmpfiles exited $tmpfiles_status"
else
    owner="$(id -u):$(id -g)"
    [[ $tmpfiles_status -eq 0 || $tmpfiles_status -eq 73 ]] ||
        fail "systemd-tmpfiles exited $tmpfiles_status"
fi
for dir in /var/lib/steerseg /var/lib/steerseg/export /var/lib/steerseg/autosave; do
    [[ $(stat -c '%a %u:%g' "$root$dir" 2>/dev/null || true) == "750 $owner" ]] ||
        fail "tmpfiles: $dir is not a 0750 folder of $owner"
done

step "hardening (readelf)"
# Full RELRO: a read-only GOT after start-up needs both the relro segment and immediate binding.
elf_dynamic=$(readelf -d "$root/usr/bin/steerseg")
grep -q 'BIND_NOW' <<<"$elf_dynamic" || grep -q 'FLAGS_1.*NOW' <<<"$elf_dynamic" ||
    fail "usr/bin/steerseg is not linked with -z now"
readelf -l "$root/usr/bin/steerseg" | grep -q 'GNU_RELRO' || fail "usr/bin/steerseg has no RELRO"

step "udev helper: radial controller by report descriptor"
hid="$work/hidraw"
mkdir -p "$hid/device"
printf '\x05\x01\x09\x0e\xa1\x01\x85\x01' >"$hid/device/report_descriptor"
"$root/usr/lib/steerseg/is-radial-controller" "$hid" || fail "a radial controller was not matched"
printf '\x05\x01\x09\x06\xa1\x01\x05\x07\x09\x0e' >"$hid/device/report_descriptor" # a keyboard
! "$root/usr/lib/steerseg/is-radial-controller" "$hid" || fail "a keyboard was matched"

step "steerseg --self-test from the root, with its site config"
# The root's /etc/steerseg/steerseg.toml, its /var/lib paths moved into the root.
sed "s|/var/lib/steerseg|$root/var/lib/steerseg|g" "$root/etc/steerseg/steerseg.toml" >"$work/site.toml"
self_test() {
    "$@" "$root/usr/bin/steerseg" --self-test --config "$work/site.toml" >"$work/self-test.log" 2>&1
}
if ! self_test env; then
    fail "self-test failed"
fi
cat "$work/self-test.log"
grep -Eq "^  ok    config: built-in defaults < .*$work/site.toml" "$work/self-test.log" ||
    fail "self-test did not apply the site config"
grep -q "^  ok    export folder: $root/var/lib/steerseg/export writable" "$work/self-test.log" ||
    fail "self-test did not check the site's export folder"
grep -q "^  ok    shaders: " "$work/self-test.log" || fail "self-test built no shaders"
# As the service's user (its uid from the root's passwd), where this test may switch users.
if [[ $(id -u) -eq 0 ]] && command -v setpriv >/dev/null; then
    uid=$(awk -F: '$1 == "steerseg" { print $3 }' "$root/etc/passwd")
    gid=$(awk -F: '$1 == "steerseg" { print $4 }' "$root/etc/passwd")
    chmod o+r "$work/site.toml"
    if self_test setpriv --reuid="$uid" --regid="$gid" --clear-groups; then
        echo "as uid $uid: passed"
    else
        cat "$work/self-test.log"
        fail "self-test as the service's user"
    fi
fi
# A broken site file fails the check, and the status says so.
printf '[export]\nfolder = 3\n' >"$work/broken.toml"
status=0
"$root/usr/bin/steerseg" --self-test --config "$work/broken.toml" >"$work/broken.log" 2>&1 || status=$?
[[ $status -eq 1 ]] || fail "self-test on a broken config exited $status, not 1"
grep -q "^  FAIL  config: 1 problem" "$work/broken.log" || { cat "$work/broken.log"; fail "no FAIL config line"; }

step "systemd-analyze verify"
# Against the root (its /usr/bin/steerseg), with this machine's units for the targets the unit
# names. Unknown keys are only warnings (status 0), so any output fails. In a container the
# result is the same: verify loads files, it does not talk to a running systemd.
cp -an /lib/systemd/system/. "$root/lib/systemd/system/"
if ! systemd-analyze verify --man=no --root="$root" /lib/systemd/system/steerseg-kiosk.service \
    >"$work/verify.log" 2>&1 || [[ -s $work/verify.log ]]; then
    cat "$work/verify.log"
    fail "systemd-analyze verify (above)"
fi

if [[ $fails -gt 0 ]]; then
    echo "package test: $fails check(s) failed"
    exit 1
fi
echo "package test: passed"
