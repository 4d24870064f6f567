#!/usr/bin/env bash
# The measurements behind results/drivers/README.md: the system's Mesa 22.3.6 against Mesa 25.0.7
# (Debian bookworm-backports, unpacked by `bash scripts/install-deps.sh driver`), both on LLVM 15, for
# every technique of the registry on GL and, where a technique has a Vulkan form, on Vulkan. The
# configurations are results/drivers/suite.json's (aircraft x40 and point_light, 256x256).
#   work.csv        one census frame per configuration and driver (plain runs with --driver): the
#                   application's work and the driver's, pass by pass (tools/driver_study.py tells them apart)
#   images/         that frame's colour (--screenshot) and visibility (--visibility) per driver; scratch,
#                   not committed (the tables say what differs; diff-*.png show the largest differences)
#   ci-instructions/  bench ci with the two drivers as its sides, layer B: instructions per frame under
#                   callgrind for the suite's subset (report.md, report.json, instructions.json; callgrind/
#                   is scratch)
#   ci-wall/        the same, layer C: wall time in interleaved rounds with an A/A control (report.md,
#                   report.json, wall.csv)
#   tables.md       the README's tables (/usr/bin/python3 tools/driver_study.py OUT)
# A driver that is not installed, a run that fails or a GL run that did not load the driver's EGL stops
# the script with one line and a non-zero exit.
# Usage: bash scripts/driver-study.sh [output folder, default results/drivers] [section ...]
#   sections: work instructions wall (default: all; about 15 minutes on 2 cores)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/results/drivers}"
shift || true
sections=("$@")
[ ${#sections[@]} -gt 0 ] || sections=(work instructions wall)
bench="$root/build/bench"
suite="$root/results/drivers/suite.json"
base_driver=system
head_driver=mesa-25.0.7
[ -x "$bench" ] || bash "$root/scripts/build.sh"
mkdir -p "$out"
wanted() { [[ " ${sections[*]} " == *" $1 "* ]]; }
die() {
    echo "driver-study: $*" >&2
    exit 1
}

# The driver must load before anything is measured: bench says in one line why not (exit 3: not
# installed, with the command that installs it).
for driver in "$base_driver" "$head_driver"; do
    msg="$("$bench" --driver "$driver" -t none --size 16x16 --frames 1 --warmup 0 --no-timer-check -q \
        2>&1 >/dev/null)" && code=0 || code=$?
    if [ "$code" -ne 0 ]; then
        echo "driver-study: driver $driver: ${msg##*$'\n'}" >&2
        exit "$code"
    fi
done

# bench ci's two sides, each on its driver (core/DriverTable: the same environment as --driver). Layer B
# pins LD_BIND_NOW=1 as the gate does; that needs the backported libdrm that install-deps.sh unpacks into
# the driver's prefix (results/drivers/README.md, "Instructions per frame").
ci_sides=(--base-driver "$base_driver" --head-driver "$head_driver")

# name<TAB>argument<TAB>argument... per configuration, the suite's common arguments first.
configs() {
    /usr/bin/python3 -c '
import json, sys
s = json.load(open(sys.argv[1]))
for c in s["configs"]:
    print("\t".join([c["name"]] + s["args"] + c["args"]))' "$suite"
}

if wanted work; then
    rm -f "$out/work.csv"
    rm -rf "$out/images"
    mkdir -p "$out/images/$base_driver" "$out/images/$head_driver"
    while IFS=$'\t' read -r -a line; do
        name="${line[0]}"
        for driver in "$base_driver" "$head_driver"; do
            echo "+ bench --driver $driver ${line[*]:1}" >&2
            "$bench" --driver "$driver" "${line[@]:1}" --frames 1 --warmup 0 --no-timer-check -q \
                --csv "$out/work.csv" --screenshot "$out/images/$driver/$name.png" \
                --visibility "$out/images/$driver/$name.vis.png" >/dev/null ||
                die "$name on $driver failed (exit $?)"
        done
    done < <(configs)
fi

# Each layer in a bench ci of its own (ci-instructions/, ci-wall/), so that one can be measured again
# alone. The layers only report here (--advisory): a driver A/B is expected to differ.
ci() { # section, layer
    rm -rf "$out/ci-$1"
    echo "+ bench ci --suite $suite --out $out/ci-$1 --layers $2 (sides: $base_driver, $head_driver)" >&2
    "$bench" ci --suite "$suite" --out "$out/ci-$1" "${ci_sides[@]}" --layers "$2" --advisory "$2" >/dev/null ||
        die "bench ci --layers $2 failed (exit $?; $out/ci-$1/report.md says why)"
}
if wanted instructions; then ci instructions B; fi
if wanted wall; then ci wall C; fi

/usr/bin/python3 "$root/tools/driver_study.py" "$out" | tee "$out/tables.md"
