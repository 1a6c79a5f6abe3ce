#!/bin/sh
# SPDX-License-Identifier: MIT
# Tests of the billiards demo (make test-demo).
# usage: demo/tests/test_demo.sh BILLIARDS_BINARY PNG_CHECK_BINARY
set -u
BIN=$1
PNG_CHECK=$2
DEMO=$(cd "$(dirname "$0")/.." && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
c2d_tally_name=test_demo
. "$DEMO/../tests/harness/tally.sh"

# check WHAT STATUS: counts one result (tally.sh); "ok - WHAT" when it passed
check() { if [ "$2" = 0 ]; then c2d_passed; echo "ok - $1"; else c2d_failed "$1"; fi; }

# --- the layers (demo/demo.mk): pool/ (the simulation) <- game/ (8-ball) <-
# app/ (the program) <- web/ (the browser build's hook, its PNG writer and the
# same-bits driver); tests/ test pool/ and game/ (and share tests/check.h).
# Every include of ours names its layer ("pool/sim.h"; the library's
# collide2d.h and collide2d_world.h aside)
# and a layer includes only itself and the layers below it; pool/, game/
# and tests/ use no SDL (they are compiled and linked without it).
# layer_check LAYER "ALLOWED LAYERS" SDL(yes|no): prints each violation, and
# "LAYER: F files, I includes"
layer_check() {
    layer=$1 allowed=$2 sdl=$3
    set --
    for f in "$DEMO/$layer"/*.h "$DEMO/$layer"/*.cpp; do
        if [ -f "$f" ]; then set -- "$@" "$f"; fi
    done
    awk -v layer="$layer" -v allowed=" $allowed " -v sdl="$sdl" -v demo="$DEMO/" '
        function bad(why) { printf "    %s:%d: %s: %s\n", substr(FILENAME, length(demo) + 1), FNR, why, $0; found = 1 }
        FNR == 1 { files++ }
        /^[ \t]*#[ \t]*include/ {
            includes++
            t = $0
            sub(/^[ \t]*#[ \t]*include[ \t]*/, "", t)
            quote = substr(t, 1, 1)
            name = substr(t, 2)
            sub(/[">].*$/, "", name)
            top = name
            if (!sub(/\/.*$/, "", top)) top = ""
            if (top ~ /^(pool|game|app|tests|tools|web)$/) { if (index(allowed, " " top " ") == 0) bad("includes from " top "/") }
            else if (quote == "\"" && name !~ /^collide2d(_world)?\.h$/) bad("an include of ours without its layer")
            if (sdl == "no" && name ~ /SDL/) bad("SDL")
        }
        sdl == "no" && /SDL_[A-Za-z]/ && !/^[ \t]*#[ \t]*include/ { bad("SDL") }
        END { printf "    %s: %d files, %d includes\n", layer, files, includes; exit (found || files == 0 || includes == 0) }
    ' "$@" < /dev/null
}
layer_check pool "pool" no; check "pool/: no SDL, includes only pool/" $?
layer_check game "game pool" no; check "game/: no SDL, includes only game/ and pool/" $?
layer_check app "app game pool" yes; check "app/: includes only app/, game/ and pool/" $?
layer_check tests "tests game pool" no; check "tests/: no SDL, includes only tests/, game/ and pool/" $?
layer_check web "web app game pool" yes; check "web/: includes only web/, app/, game/ and pool/" $?
[ -z "$(ls "$DEMO"/*.h "$DEMO"/*.cpp 2>/dev/null)" ]; check "every source of the demo is in a layer" $?

# json_get FILE KEY: the value of a scalar key of the one-line JSON object
json_get() { sed -n "s/.*\"$2\":\([^,}]*\).*/\1/p" "$1"; }

# --- elastic scene, collide2d response: energy kept, nothing escapes or tunnels
"$BIN" --headless --scene elastic --seconds 60 --json > "$TMP/elastic.json"
check "elastic 60 s runs" $?
drift=$(awk -v a="$(json_get "$TMP/elastic.json" energy_start)" -v b="$(json_get "$TMP/elastic.json" energy_end)" \
    'BEGIN { d = b / a - 1; if (d < 0) d = -d; printf "%.3g", d }')
echo "    elastic: |energy_end/energy_start - 1| = $drift"
awk -v d="$drift" 'BEGIN { exit !(d < 1e-9) }'; check "elastic energy drift < 1e-9" $?
[ "$(json_get "$TMP/elastic.json" escaped)" = 0 ]; check "elastic escaped 0" $?
[ "$(json_get "$TMP/elastic.json" tunnelled)" = 0 ]; check "elastic tunnelled 0" $?
awk -v o="$(json_get "$TMP/elastic.json" max_overlap)" 'BEGIN { exit !(o < 1e-9) }'; check "elastic max_overlap < 1e-9" $?
for key in scene response steps sim_seconds wall_seconds balls ball_ball_collisions cushion_collisions pocketed \
           escaped tunnelled max_overlap energy_start energy_end momentum_start momentum_end check checked_pairs \
           max_energy_step; do
    grep -q "\"$key\":" "$TMP/elastic.json" || { echo "    missing key $key"; key=missing; break; }
done
[ "$key" != missing ] && [ "$(wc -l < "$TMP/elastic.json")" = 1 ]; check "JSON has every key, one object" $?

# --- the tunnelling check can fail: Box2D's own solver tunnels at break speed
"$BIN" --headless --scene elastic --response box2d --seconds 10 --json > "$TMP/box2d.json"
echo "    box2d response: tunnelled $(json_get "$TMP/box2d.json" tunnelled), max_overlap $(json_get "$TMP/box2d.json" max_overlap)"
[ "$(json_get "$TMP/box2d.json" tunnelled)" -gt 0 ]; check "checker sees Box2D solver tunnelling" $?

# --- determinism: same flags, same JSON apart from wall_seconds
strip_wall() { sed 's/"wall_seconds":[^,]*,//' "$1"; }
for args in "--scene break" "--scene break --response box2d --shot 10,11 --seed 7" "--scene gas --balls 500 --seconds 5 --seed 3"; do
    # shellcheck disable=SC2086
    "$BIN" --headless --json $args > "$TMP/run1.json"
    # shellcheck disable=SC2086
    "$BIN" --headless --json $args > "$TMP/run2.json"
    [ "$(strip_wall "$TMP/run1.json")" = "$(strip_wall "$TMP/run2.json")" ] && [ -s "$TMP/run1.json" ]
    check "deterministic: $args" $?
done

# --- break: the game's scene ends at rest with balls in pockets, none lost
"$BIN" --headless --json --trace "$TMP/break.csv" > "$TMP/break.json"
[ "$(json_get "$TMP/break.json" energy_end)" = 0 ] && [ "$(json_get "$TMP/break.json" escaped)" = 0 ] &&
    [ "$(json_get "$TMP/break.json" tunnelled)" = 0 ]
check "break comes to rest, escaped 0, tunnelled 0" $?
[ "$(($(wc -l < "$TMP/break.csv") - 2))" = "$(json_get "$TMP/break.json" steps)" ] &&
    head -1 "$TMP/break.csv" | grep -q '^time,kinetic_energy,momentum_x,momentum_y$'
check "trace has a header and a row per frame" $?

# --- bad input: message on stderr, exit status 2
bad() {
    "$BIN" --headless "$@" > "$TMP/out" 2> "$TMP/err"
    status=$?
    if [ "$status" = 2 ] && [ -s "$TMP/err" ] && [ ! -s "$TMP/out" ]; then c2d_passed; echo "ok - bad input exits 2: $*"
    else c2d_failed "bad input exits 2: $* (status $status)"; fi
}
bad --no-such-flag
bad --seconds abc
bad --seconds -1
bad --seconds nan
bad --seconds 1e999
bad --seconds
bad --scene gas --balls 0
bad --scene gas --balls -5
bad --scene gas --balls 12x
bad --balls 10
bad --scene snooker
bad --response physx
bad --shot 10
bad --shot 0,-3
bad --shot 0,0
bad --shot abc,5
bad --seed -1
bad --seed 1.5
bad stray-argument
bad --shot 0,2,0.1
bad --shot 0,2,0.4,0.4
bad --shot 0,2,0.5,x
bad --shot 0,2,0,0,-5
bad --shot 0,2,0,0,86
bad --shot 0,2,0,0,nan
bad --shot 0,2,0,0,x
bad --shot 0,2,0,0,10,1
bad --model cylinder
bad --model
bad --model sphere --model disk
bad --cue-end-mass
bad --cue-end-mass 0
bad --cue-end-mass -5
bad --cue-end-mass 171
bad --cue-end-mass abc
bad --cue-end-mass 5g
bad --cue-end-mass nan
bad --cue-end-mass 1e-400
bad --cue-end-mass 5 --cue-end-mass 6
bad --cue-end-mass=5
bad --place 1,2
bad --place 16,1,0.6
bad --place 0,3,0.6
bad --place 0,0.01,0.6
bad --place 0,1,0.6 --place 1,1.02,0.6
bad --place 0,1,0.6 --place 0,1.5,0.6
bad --place 1,1,0.6 --shot 0,2
bad --scene gas --place 0,1,1
bad --scene cradle --balls 21
bad --scene cradle --balls 0
bad --scene cradle --place 0,1,0.6
bad --scene elastic --balls 5
bad --check bogus
bad --broadphase bogus
bad --broadphase
bad --check
bad --check ""
bad --trace ""
bad --events ""
bad --events /nonexistent-dir/events.csv
bad --screenshot /nonexistent-dir/shot.png

# bad_says TEXT ARGS...: bad input exits 2, its message contains TEXT, nothing on stdout
bad_says() {
    text=$1
    shift
    "$BIN" --headless "$@" > "$TMP/out" 2> "$TMP/err"
    status=$?
    if [ "$status" = 2 ] && grep -q -- "$text" "$TMP/err" && [ ! -s "$TMP/out" ]; then
        c2d_passed; echo "ok - bad input says '$text': $*"
    else c2d_failed "bad input says '$text': $* (status $status: $(cat "$TMP/err"))"; fi
}

# --- numbers: underflow and overflow say so, as do a stray tail,
# an empty value, a leading blank (strtoull read " -1" as 2^64 - 1) and a
# negative count
bad_says "'1e-320' underflows" --seconds 1e-320
bad_says "'1e-400' underflows" --seconds 1e-400
bad_says "underflows" --shot 0,1e-320
bad_says "underflows" --place 0,1,4e-324
bad_says "'1e400' overflows" --seconds 1e400
bad_says "overflows" --shot -1e400,3
bad_says "overflows" --seed 99999999999999999999
bad_says "not a finite number" --seconds inf
bad_says "NaN" --seconds nan
bad_says "stray 'x'" --seconds 1.5x
bad_says "stray ' '" --seconds "1 "
bad_says "empty value" --seconds ""
bad_says "empty value" --shot 0,
bad_says "empty value" --seed ""
bad_says "starts with a blank" --seed " -1"
bad_says "starts with a blank" --seconds " 1"
bad_says "(0, 170] grams" --cue-end-mass 0
bad_says "(0, 170] grams" --cue-end-mass 170.5
bad_says "give the value as the next argument" --cue-end-mass=5
bad_says "negative" --seed -1
bad_says "negative" --scene gas --balls -5
"$BIN" --headless --seconds 0 --json > "$TMP/zero.json" && [ "$(json_get "$TMP/zero.json" steps)" = 0 ]
check "--seconds 0 is no underflow" $?

# --- repeated options: --place and --shot accumulate, the
# switches (--headless, --json) may repeat; any other option taking a value
# given twice is an error naming it, and nothing is written
for opt in "--scene break" "--response box2d" "--balls 5" "--seed 3" "--check sample" "--broadphase cells" "--game 8ball" "--players computer,computer" \
           "--seconds 1" "--events $TMP/twice1.csv" "--trace $TMP/twice2.csv" "--speeds $TMP/twice3.txt" \
           "--screenshot $TMP/twice4.png" "--screenshot-window $TMP/twice5.png"; do
    # shellcheck disable=SC2086
    bad_says "${opt%% *} given twice" $opt $opt
done
[ -z "$(ls "$TMP" | grep twice)" ]; check "a repeated option writes no file" $?
bad_says "a.png', then '$TMP/b.png'" --screenshot "$TMP/a.png" --screenshot "$TMP/b.png"
"$BIN" --headless --headless --json --json --seconds 0 > "$TMP/out" && [ "$(wc -l < "$TMP/out")" = 1 ]
check "switches may repeat: --headless --headless --json --json" $?
"$BIN" --help | grep -q -- "--place and --shot may repeat"; check "--help says which options may repeat" $?

# --- other papercuts: --seed=3, a switch with a value, a stray
# argument, the value out of range named
bad_says "give the value as the next argument (--seed 3)" --seed=3
bad_says "--json takes no value" --json=1
bad_says "unexpected argument 'stray'" stray
bad_says "unknown option '-x'" -x
bad_says "got '90000'" --seconds 90000
bad_says "got '0'" --scene gas --balls 0
"$BIN" --help | grep -q -- "--help, -h"; check "--help lists itself" $?

# --- outputs: a value that looks like an option, two outputs in
# one file
bad_says "looks like an option" --events --json
bad_says "looks like an option" --trace -
bad_says "--trace and --events name the same file" --events "$TMP/same.csv" --trace "$TMP/same.csv"
ln -s same2.csv "$TMP/link.csv" && : > "$TMP/same2.csv"
bad_says "name the same file" --events "$TMP/same2.csv" --speeds "$TMP/link.csv"
"$BIN" --headless --seconds 0 --events /dev/null --trace /dev/null > /dev/null; check "two outputs to /dev/null are fine" $?

# --- checks before simulating: exit 2 with nothing simulated (no
# summary on stdout) and no file left behind, an existing one untouched
env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$BIN" --headless --screenshot-window "$TMP/nowin.png" \
    --events "$TMP/nowin.csv" > "$TMP/out" 2> "$TMP/err"
status=$?
[ "$status" = 2 ] && grep -q -- "--screenshot-window: no display" "$TMP/err" && [ ! -s "$TMP/out" ] &&
    [ ! -e "$TMP/nowin.png" ] && [ ! -e "$TMP/nowin.csv" ]
check "--screenshot-window without a display: exit 2 before simulating, no files" $?
env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$BIN" --screenshot-window "$TMP/nowin.png" > "$TMP/out" 2> "$TMP/err"
[ $? = 2 ] && grep -q -- "--screenshot-window: no display" "$TMP/err" && [ ! -s "$TMP/out" ] &&
    ! grep -q "running headless" "$TMP/err"
check "--screenshot-window, no display, no --headless: exit 2 before simulating, no \"running headless\"" $?
env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$BIN" --game practice > "$TMP/out" 2> "$TMP/err"
[ $? = 2 ] && grep -q -- "--game practice is played in the window" "$TMP/err" && ! grep -q "running headless" "$TMP/err"
check "--game practice, no display: exit 2, no \"running headless\"" $?
# SDL tries the display and leaks a block in libdbus doing so: not ours to
# free, so LeakSanitizer is off for this run (as for the window screenshot).
DISPLAY=:7777 ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" "$BIN" --headless --screenshot-window "$TMP/nowin.png" > "$TMP/out" 2> "$TMP/err"
[ $? = 2 ] && grep -q -- "--screenshot-window: no display" "$TMP/err" && [ ! -s "$TMP/out" ] && [ ! -e "$TMP/nowin.png" ]
check "--screenshot-window, an unreachable display: exit 2 before simulating" $?
echo keep > "$TMP/keep.csv"
bad_says "--speeds: /nonexistent-dir/s.txt" --screenshot "$TMP/left.png" --trace "$TMP/keep.csv" --events "$TMP/left.csv" \
    --speeds /nonexistent-dir/s.txt
[ ! -e "$TMP/left.png" ] && [ ! -e "$TMP/left.csv" ] && [ "$(cat "$TMP/keep.csv")" = keep ]
check "a failed check leaves no new file and an existing one untouched" $?
bad_says "--screenshot: $TMP" --screenshot "$TMP"
bad_says "--screenshot: /nonexistent-dir" --game 8ball --screenshot /nonexistent-dir/x.png

# --- stdout: a failed write of --help, the summary or the JSON
# is exit 1 with a message
"$BIN" --help > "$TMP/out" && head -1 "$TMP/out" | grep -q '^usage: billiards'; check "--help: usage, exit 0" $?
"$BIN" --help > /dev/full 2> "$TMP/err"
[ $? = 1 ] && grep -q "standard output" "$TMP/err"; check "--help to a full disk: exit 1 and a message" $?
"$BIN" --headless > /dev/full 2> "$TMP/err"
[ $? = 1 ] && grep -q "standard output" "$TMP/err"; check "the summary to a full disk: exit 1 and a message" $?
"$BIN" --headless --game 8ball --json > /dev/full 2> "$TMP/err"
[ $? = 1 ] && grep -q "standard output" "$TMP/err"; check "8-ball JSON to a full disk: exit 1 and a message" $?
"$BIN" --help >&- 2> "$TMP/err"
[ $? = 1 ] && grep -q "standard output" "$TMP/err"; check "--help to a closed stdout: exit 1 and a message" $?

# --- write errors: exit 1 and a message
"$BIN" --headless --events /dev/full > /dev/null 2> "$TMP/err"
[ $? = 1 ] && [ -s "$TMP/err" ]; check "a full disk for --events: exit 1 and a message" $?
"$BIN" --headless --json > /dev/full 2> "$TMP/err"
[ $? = 1 ] && [ -s "$TMP/err" ]; check "a full disk for stdout: exit 1 and a message" $?

# --- headless-only options are refused in a window, before any SDL output
DISPLAY=:7777 "$BIN" --json --seconds 1 > "$TMP/out" 2> "$TMP/err"
status=$?
[ "$status" = 2 ] && grep -q -- "--json" "$TMP/err" && grep -q -- "--headless" "$TMP/err" && [ ! -s "$TMP/out" ]
check "window mode refuses --json and --seconds with a message" $?
DISPLAY=:7777 "$BIN" --cue-end-mass 8 --model disk --json > "$TMP/out" 2> "$TMP/err"
[ $? = 2 ] && grep -q -- "--json: only" "$TMP/err" && ! grep -q -- "--cue-end-mass" "$TMP/err"
check "window mode takes --cue-end-mass (only --json refused)" $?
env -u DISPLAY -u WAYLAND_DISPLAY -u XDG_RUNTIME_DIR "$BIN" --seconds 1 > /dev/null 2> "$TMP/err"
head -1 "$TMP/err" | grep -q '^billiards: no display' && ! grep -q XDG_RUNTIME_DIR "$TMP/err"
check "no display: our message first, none from SDL" $?

# --- --seconds is honoured up to the 86400 the help allows (no hidden cap)
"$BIN" --headless --place 0,1,0.6 --seconds 7300 --json > "$TMP/long.json"
[ "$(json_get "$TMP/long.json" steps)" = 438000 ]; check "--seconds 7300 runs 438000 frames" $?

# --- --model and the cue's elevation: each model by name in the JSON; the
# elevated shot runs; the disk model's straight draw is the former contact's
for m in sphere sphere-alciatore disk; do
    "$BIN" --headless --model $m --place 0,0.8,0.635 --place 1,1.3,0.635 --shot 0,2,0,-0.5,30 --json > "$TMP/model.json" &&
        grep -q "\"contact_model\":\"$m\"" "$TMP/model.json"
    check "--model $m: named in the JSON, an elevated draw shot runs" $?
done

# --- --cue-end-mass: the JSON's squirt_end_mass (kg) is the setting, m/30
# without it; the strike's squirt is TP A.31's with that end mass (awk
# computes it from the JSON's ball mass), and a heavier end mass squirts more
for g in default 3 12; do
    if [ "$g" = default ]; then set --; else set -- --cue-end-mass "$g"; fi
    "$BIN" --headless "$@" --place 0,0.5,0.635 --shot 0,1,0.3,0 --events "$TMP/squirt_$g.csv" --json > "$TMP/squirt_$g.json"
    me=$(json_get "$TMP/squirt_$g.json" squirt_end_mass)
    m=$(json_get "$TMP/squirt_$g.json" ball_mass)
    awk -F, -v g="$g" -v me="$me" -v m="$m" '$2 == "strike" {
            want_me = g == "default" ? m / 30 : g / 1000
            s = 0.3; a = atan2(2.5 * s * sqrt(1 - s * s), 1 + m / me + 2.5 * (1 - s * s))
            got = atan2($8, $7)
            printf "    --cue-end-mass %s: squirt_end_mass %s kg, leaves at %.6f deg (TP A.31 %.6f)\n", g, me, got * 45 / atan2(1, 1), a * 45 / atan2(1, 1)
            d = got - a; ok = (me - want_me < 1e-15 && want_me - me < 1e-15 && d < 1e-12 && -d < 1e-12) }
        END { exit !ok }' "$TMP/squirt_$g.csv"
    check "--cue-end-mass $g: reported in the JSON, the strike squirts as TP A.31" $?
done
[ "$(json_get "$TMP/squirt_default.json" squirt_end_mass)" = 0.0056666666666666671 ] &&
    awk -F, 'FNR == 2 { a[++n] = $8 / $7 } END { exit !(n == 3 && a[2] < a[1] && a[1] < a[3]) }' \
        "$TMP/squirt_default.csv" "$TMP/squirt_3.csv" "$TMP/squirt_12.csv"
check "--cue-end-mass: the default's bits are m/30's; 3 g squirts less, 12 g more" $?

# --- --place, --shot with spin, --events, the JSON model and final state
"$BIN" --headless --place 0,0.1,0.635 --shot 0,0.5 --events "$TMP/slide.csv" --json > "$TMP/slide.json"
head -1 "$TMP/slide.csv" | grep -q '^time,kind,ball,other,x,y,vx,vy,wx,wy,wz$' &&
    sed -n 2p "$TMP/slide.csv" | grep -q '^0,strike,0,-1,' &&
    awk -F, 'NR > 1 { if ($1 < t) bad = 1; t = $1; if ($2 !~ /^(ball_ball|cushion|jaw|pocket|strike|slide_to_roll|roll_to_spin|stop)$/) bad = 1 }
             END { exit bad }' "$TMP/slide.csv"
check "--events: header, strike first, known kinds in time order" $?
mu=$(json_get "$TMP/slide.json" mu_slide)
g=$(json_get "$TMP/slide.json" gravity)
awk -F, -v mu="$mu" -v g="$g" '$2 == "slide_to_roll" {
        d = $5 - 0.1; want = 12 * 0.25 / (49 * mu * g)
        printf "    centre ball at 0.5 m/s: slid %.9f m (12 v^2 / 49 mu_s g = %.9f), then %.9f m/s (5v/7 = %.9f)\n", d, want, $7, 2.5 / 7
        ok = (d - want < 1e-9 && want - d < 1e-9 && $7 - 2.5 / 7 < 1e-12 && 2.5 / 7 - $7 < 1e-12) }
    END { exit !ok }' "$TMP/slide.csv"
check "--events: the slide ends after 12 v^2 / (49 mu_s g) at 5/7 of v" $?
for key in model mu_slide mu_roll mu_spin ball_restitution ball_friction cushion_restitution cushion_friction \
           corner_mouth side_mouth scratches ball_count; do
    grep -q "\"$key\":" "$TMP/slide.json" || { echo "    missing key $key"; key=missing; break; }
done
[ "$key" != missing ] && [ "$(json_get "$TMP/slide.json" ball_count)" = 1 ] &&
    grep -q '"balls":\[{"number":0,"x":[^,]*,"y":0.63500000000000001,"vx":0,"vy":0,"wx":0,"wy":0,"wz":0,"state":"stationary","on_table":true}\]' "$TMP/slide.json"
check "JSON: the model by name, and each ball's final state" $?
"$BIN" --headless --place 0,0.5,0.5 --shot 225,1 --json > "$TMP/scratch.json"
"$BIN" --headless --place 0,0.6,0.3 --place 1,0.4,0.2 --shot 206.565,2 --json > "$TMP/pot.json"
[ "$(json_get "$TMP/scratch.json" scratches)" = 1 ] && [ "$(json_get "$TMP/scratch.json" pocketed)" = 0 ] &&
    [ "$(json_get "$TMP/pot.json" scratches)" = 0 ] && [ "$(json_get "$TMP/pot.json" pocketed)" = 1 ] &&
    grep -q '"number":1,[^}]*"state":"pocketed","on_table":false' "$TMP/pot.json"
check "pocketed counts object balls, scratches the cue ball" $?
"$BIN" --headless --place 0,0.8,0.4 --place 3,1.6,0.7 --shot 20,3,0.3,-0.2 --shot 180,2,-0.2,0.3 --json > "$TMP/run1.json"
"$BIN" --headless --place 0,0.8,0.4 --place 3,1.6,0.7 --shot 20,3,0.3,-0.2 --shot 180,2,-0.2,0.3 --json > "$TMP/run2.json"
[ "$(strip_wall "$TMP/run1.json")" = "$(strip_wall "$TMP/run2.json")" ] && [ "$(json_get "$TMP/run1.json" tunnelled)" = 0 ]
check "deterministic with --place and spin shots" $?

# --- gas: the speed distribution relaxes to 2-D Maxwell-Boltzmann (Rayleigh).
# One-sample Kolmogorov-Smirnov distance against the Rayleigh CDF whose sigma^2
# is the sample's mean v^2 / 2 (set by the kinetic energy).  Bound: the
# asymptotic critical value at alpha = 0.001, 1.9495 / sqrt(n).  Estimating
# sigma from the sample only makes D smaller (Lilliefors), so a relaxed gas
# fails with probability < 0.1%; the run is deterministic, so it cannot flake.
# The same statistic on the starting (uniform-component) velocities must
# exceed the bound, showing the test can tell the difference.
ks() {
    sort -g "$1" | awk '
        { v[NR] = $1; s2 += $1 * $1 }
        END {
            n = NR; sig2 = s2 / n / 2; d = 0
            for (i = 1; i <= n; i++) {
                f = 1 - exp(-v[i] * v[i] / (2 * sig2))
                if (i / n - f > d) d = i / n - f
                if (f - (i - 1) / n > d) d = f - (i - 1) / n
            }
            printf "%.5f %.5f\n", d, 1.9495 / sqrt(n)
        }'
}
"$BIN" --headless --scene gas --balls 2000 --seconds 10 --speeds "$TMP/relaxed.txt" --json > "$TMP/gas.json"
"$BIN" --headless --scene gas --balls 2000 --seconds 0 --speeds "$TMP/start.txt" > /dev/null
set -- $(ks "$TMP/relaxed.txt"); d_relaxed=$1; bound=$2
set -- $(ks "$TMP/start.txt"); d_start=$1
echo "    gas, 2000 disks: KS D = $d_relaxed after 10 s, $d_start at start; bound $bound (alpha 0.001)"
awk -v d="$d_relaxed" -v b="$bound" 'BEGIN { exit !(d < b) }'; check "gas speeds match Rayleigh after 10 s (KS)" $?
awk -v d="$d_start" -v b="$bound" 'BEGIN { exit !(d > b) }'; check "KS rejects the non-equilibrium start" $?
[ "$(json_get "$TMP/gas.json" tunnelled)" = 0 ] && [ "$(json_get "$TMP/gas.json" escaped)" = 0 ]
check "gas tunnelled 0, escaped 0" $?

# --- --broadphase tree|cells: who finds the world's candidates changes no
# bit of the events (the world's contract)
bad_says "--broadphase: unknown broadphase 'grid' (tree or cells)" --broadphase grid
"$BIN" --headless --events "$TMP/bp_tree.csv" > /dev/null &&
    "$BIN" --headless --broadphase cells --events "$TMP/bp_cells.csv" > /dev/null &&
    [ "$(wc -l < "$TMP/bp_tree.csv")" -gt 50 ] && cmp -s "$TMP/bp_tree.csv" "$TMP/bp_cells.csv"
check "the break's events are the same bits with Box2D's tree and the world's cells" $?

# --- --check full|sample|off (checker.h).  The JSON says which ran; off
# checks no pair; sample checks the pairs of every m-th ball, m = ceil(N /
# 1024), so up to 1,024 disks it is full, and beyond it sees each pair's
# fault with probability 1 - (1 - 1/m)^2.  Box2D's own solver tunnels in a
# 3,000-disk gas (m = 3): sample must see 5/9 of what full sees, within 5
# binomial standard deviations.
bad_says "--check: unknown mode 'all' (full, sample or off)" --check all
json_str() { sed -n "s/.*\"$2\":\"\([^\"]*\)\".*/\1/p" "$1"; }
[ "$(json_str "$TMP/gas.json" check)" = full ]; check "--check is full by default, and the JSON says so" $?
"$BIN" --headless --scene gas --balls 2000 --seconds 10 --check off --speeds "$TMP/off.txt" --json > "$TMP/gas_off.json"
[ "$(json_str "$TMP/gas_off.json" check)" = off ] && [ "$(json_get "$TMP/gas_off.json" checked_pairs)" = 0 ] &&
    cmp -s "$TMP/off.txt" "$TMP/relaxed.txt"
check "--check off checks nothing and changes nothing of the run" $?
"$BIN" --headless --scene gas --balls 1000 --seconds 5 --check full --json > "$TMP/gas_full.json"
"$BIN" --headless --scene gas --balls 1000 --seconds 5 --check sample --json > "$TMP/gas_sample.json"
[ "$(json_str "$TMP/gas_sample.json" check)" = sample ] &&
    [ "$(json_get "$TMP/gas_sample.json" checked_pairs)" = "$(json_get "$TMP/gas_full.json" checked_pairs)" ] &&
    [ "$(json_get "$TMP/gas_sample.json" checked_pairs)" -gt 0 ]
check "--check sample of 1,000 disks checks every pair full does" $?
"$BIN" --headless --scene gas --balls 3000 --seconds 10 --response box2d --check full --json > "$TMP/b2_full.json"
"$BIN" --headless --scene gas --balls 3000 --seconds 10 --response box2d --check sample --json > "$TMP/b2_sample.json"
full=$(json_get "$TMP/b2_full.json" tunnelled)
sampled=$(json_get "$TMP/b2_sample.json" tunnelled)
echo "    Box2D gas, 3000 disks: full sees $full tunnelled pairs, sample $sampled (expected 5/9 of full)"
awk -v f="$full" -v s="$sampled" 'BEGIN { p = 5 / 9; sd = sqrt(f * p * (1 - p)); exit !(f > 0 && s >= f * p - 5 * sd && s <= f * p + 5 * sd) }'
check "--check sample sees 5/9 of Box2D's tunnelling at m = 3" $?
"$BIN" --headless --scene gas --balls 3000 --seconds 10 --check sample --json > "$TMP/gas3k.json"
[ "$(json_get "$TMP/gas3k.json" tunnelled)" = 0 ] && [ "$(json_get "$TMP/gas3k.json" checked_pairs)" -gt 0 ]
check "--check sample: the world's gas of 3,000 disks tunnels nowhere" $?

# --- Newton's cradle: a head-on cue ball into N touching balls on the
# lossless table.  Textbook: the last ball leaves at v, the cue ball and the
# rest stand exactly still, after exactly N impacts (the fewest: each gap
# carries the momentum once).  Checked bit for bit over row lengths and
# speeds (the JSON's cradle object lists every ball's expected and actual
# velocity); Box2D's own solver does not reproduce it, so the check can fail.
cradle_ok=0
cradle_runs=0
for n in 1 2 3 5 8 13 20; do
    for v in 0.75 3 12; do
        "$BIN" --headless --scene cradle --balls "$n" --shot "0,$v" --json > "$TMP/cradle.json"
        c=$(sed -n 's/.*"cradle":{\(.*\)}}$/\1/p' "$TMP/cradle.json")
        expected=$(echo "$c" | sed -n 's/.*"expected":\(\[[^]]*\]\).*/\1/p')
        actual=$(echo "$c" | sed -n 's/.*"actual":\(\[[^]]*\]\).*/\1/p')
        want=$(awk -v n="$n" -v v="$v" 'BEGIN { s = "["; for (i = 0; i < n; i++) s = s "0,0,"; printf "%s%s,0]", s, v }')
        cradle_runs=$((cradle_runs + 1))
        if echo "$c" | grep -q "\"row\":$n,\"head_on\":true,\"crossed\":true,\"speed\":$v,\"impacts\":$n,\"minimal_impacts\":$n,\"exact\":true," &&
            [ "$expected" = "$want" ] && [ "$actual" = "$want" ]; then
            cradle_ok=$((cradle_ok + 1))
        else
            echo "    cradle N=$n v=$v: $c"
        fi
    done
done
echo "    cradle: $cradle_ok of $cradle_runs (N 1-20, v 0.75-12 m/s) exact with N impacts"
[ "$cradle_ok" = "$cradle_runs" ]; check "cradle: last ball leaves at v, the rest exactly still, N impacts" $?
"$BIN" --headless --scene cradle --response box2d --json > "$TMP/cradle_box2d.json"
grep -q '"cradle":{"row":5,"head_on":true,"crossed":true,.*"exact":false' "$TMP/cradle_box2d.json"
check "cradle check fails Box2D's own solver" $?
"$BIN" --headless --scene cradle --shot 180,2 --json > "$TMP/cradle_back.json"
grep -q '"head_on":false,.*"exact":false' "$TMP/cradle_back.json"
check "cradle: a shot away from the row has no textbook outcome" $?

# --- offscreen screenshot, no display at all
env -u DISPLAY -u WAYLAND_DISPLAY "$BIN" --headless --screenshot "$TMP/shot.png" > /dev/null &&
    "$PNG_CHECK" "$TMP/shot.png"
check "offscreen screenshot is a valid, non-blank PNG" $?

# --- no display: the game says so and falls back to headless
env -u DISPLAY -u WAYLAND_DISPLAY "$BIN" --seconds 1 > "$TMP/out" 2> "$TMP/err"
status=$?
[ "$status" = 0 ] && grep -qi "display" "$TMP/err" && grep -q "break scene" "$TMP/out"
check "no display: message and headless fallback" $?

# --- a real window under Xvfb draws the table.  Under SANITIZE=1, leak
# reports are off for this one run: SDL dlopen()s the X11/D-Bus libraries and
# unloads them, so their own allocations show as leaks of "unknown module"s
# that no suppression can name; every other run here keeps leak checks on.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" xvfb-run -a "$BIN" --headless --screenshot-window "$TMP/window.png" > /dev/null 2> "$TMP/err" &&
    "$PNG_CHECK" "$TMP/window.png"
status=$?
[ "$status" = 0 ] || cat "$TMP/err"
check "window under Xvfb draws the table" $status

# --- 8-ball, computer against computer: a winner by the rules, the same game
# from the same seed, the shots in the JSON; a human player needs the window
strip_clock() { sed 's/"wall_seconds":[^,]*,//; s/"think_seconds":[^,]*,//' "$1"; }
for seed in 1 2 3; do
    "$BIN" --headless --game 8ball --players computer,computer --seed $seed --json > "$TMP/game$seed.json"
    winner=$(json_get "$TMP/game$seed.json" winner)
    echo "    8-ball seed $seed: $(json_get "$TMP/game$seed.json" shot_count) shots, $(json_get "$TMP/game$seed.json" fouls) fouls, winner $winner, $(json_get "$TMP/game$seed.json" reason)"
    { [ "$winner" = 0 ] || [ "$winner" = 1 ]; } && grep -q '"number":8,[^}]*"on_table":false' "$TMP/game$seed.json" &&
        grep -q '"shots":\[{"player":0,"angle":[^,]*,"speed":[^,]*,"side":[^,]*,"topback":[^,]*,"ball_in_hand":null,"potted":\[[0-9,]*\],"foul":"[a-z_]*"' "$TMP/game$seed.json"
    check "8-ball seed $seed: runs to a winner on the 8, shots in the JSON" $?
done
"$BIN" --headless --game 8ball --seed 1 --json > "$TMP/again.json"
[ "$(strip_clock "$TMP/game1.json")" = "$(strip_clock "$TMP/again.json")" ]; check "8-ball: same seed, same JSON" $?
[ "$(strip_clock "$TMP/game1.json")" != "$(strip_clock "$TMP/game2.json")" ]; check "8-ball: another seed, another game" $?
bad --game 8ball --players human,computer
bad --game 8ball --players computer
bad --game 8ball --players computer,robot
bad --game chess
bad --players computer,computer
bad --game 8ball --shot 0,3
bad --game 8ball --place 0,1,0.6
bad --game 8ball --scene elastic
bad --game 8ball --seconds 10
bad --game practice

# --- 9-ball, computer against computer: a winner by the 9 (or three fouls),
# the game named in the JSON, the same game from the same seed
for seed in 1 2; do
    "$BIN" --headless --game 9ball --seed $seed --json > "$TMP/nine$seed.json"
    winner=$(json_get "$TMP/nine$seed.json" winner)
    echo "    9-ball seed $seed: $(json_get "$TMP/nine$seed.json" shot_count) shots, winner $winner, $(json_get "$TMP/nine$seed.json" reason)"
    { [ "$winner" = 0 ] || [ "$winner" = 1 ]; } && grep -q '"game":"9ball"' "$TMP/nine$seed.json" &&
        { grep -q '"number":9,[^}]*"on_table":false' "$TMP/nine$seed.json" || grep -q 'third foul' "$TMP/nine$seed.json"; } &&
        ! grep -q '"number":1[0-5],' "$TMP/nine$seed.json"
    check "9-ball seed $seed: runs to a winner, nine balls only, named in the JSON" $?
done
"$BIN" --headless --game 9ball --seed 1 --json > "$TMP/nine-again.json"
[ "$(strip_clock "$TMP/nine1.json")" = "$(strip_clock "$TMP/nine-again.json")" ]; check "9-ball: same seed, same JSON" $?
bad --game 9ball --players human,computer
bad --game 9ball --shot 0,3

c2d_summary
