#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""test_web.py - the game in headless Chromium (make test-web).

Serves build/web on 127.0.0.1 (a free port), drives Chromium through
selenium and checks: the page loads with the rack on the table; the break
through window.collide2d ends with the native headless run's positions bit
for bit (billiards --headless --json, and the simulation alone, same_bits),
and a shot with spin from another rack too; a shot by mouse drag moves the
cue ball; a tap to aim then a drag on a phone's screen (390x844 CSS pixels
at 3 device pixels each, touch events) shoots; the canvas fills the window;
a screenshot of the canvas is not blank.  Prints the frame rate (frames
drawn per second of wall time; a measurement, not asserted).

Usage: test_web.py WEBDIR BILLIARDS SAME_BITS [--screenshot FILE.png]
Debian's /usr/bin/python3 has selenium (python3-selenium); Chromium runs as
root with --no-sandbox, WebGL on SwiftShader.
"""
import functools
import http.server
import json
import struct
import subprocess
import sys
import threading
import time
import zlib

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

passed = failed = 0


def check(ok, what):
    global passed, failed
    print(("ok - " if ok else "FAIL - ") + what, flush=True)
    if ok:
        passed += 1
    else:
        failed += 1


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(root):
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=root))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def browser(width, height, phone=False):
    """Headless Chromium, a desktop window or (phone) a phone's screen emulated:
    its viewport in CSS pixels, 3 device pixels to each, touch events."""
    options = webdriver.ChromeOptions()
    for arg in ("--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
                "--autoplay-policy=no-user-gesture-required", "--window-size=%d,%d" % (width, height)):
        options.add_argument(arg)
    if phone:
        options.add_experimental_option("mobileEmulation", {"deviceMetrics": {"width": width, "height": height, "pixelRatio": 3.0, "touch": True}})
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def wait(driver, script, seconds, step=0.1):
    """Polls a script until it is truthy; its last value (falsy on time-out)."""
    end = time.time() + seconds
    while True:
        value = driver.execute_script(script)
        if value or time.time() > end:
            return value
        time.sleep(step)


def open_page(driver, base, query):
    driver.get(base + "/index.html" + query)
    return wait(driver, "return !!window.collide2d && window.collide2d.atRest()", 120, 0.25)


def balls(obj):
    return [(b["number"], b["x"], b["y"], b["on_table"]) for b in obj["balls"]]


def native(billiards, same_bits, seed, shot):
    game = json.loads(subprocess.check_output(
        [billiards, "--headless", "--json", "--seed", str(seed), "--shot", ",".join(map(str, shot))]))
    alone = json.loads(subprocess.check_output([same_bits, str(seed)] + [str(v) for v in shot]))
    return balls(game), balls(alone)


FILLS = ("var c = document.getElementById('canvas'), r = c.getBoundingClientRect();"
         "return [r.width, r.height, window.innerWidth, window.innerHeight, c.width, c.height, window.devicePixelRatio];")


def fills(driver):
    """The canvas covers the window, its pixels at the device's ratio."""
    w, h, iw, ih, pw, ph, ratio = driver.execute_script(FILLS)
    return abs(w - iw) <= 1 and abs(h - ih) <= 1 and abs(pw - w * ratio) <= 2 and abs(ph - h * ratio) <= 2, (iw, ih, pw, ph)


def cue(driver):
    for b in driver.execute_script("return window.collide2d.state()")["balls"]:
        if b["number"] == 0:
            return (b["x"], b["y"], b["on_table"])
    return None


def png_pixels(data):
    """(width, height, list of pixel tuples) of an 8-bit RGB/RGBA PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    at, idat, width, height, channels = 8, b"", 0, 0, 0
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6)
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    pixels = [tuple(r[i:i + 3]) for r in rows for i in range(0, stride, channels)]
    return width, height, pixels


def main():
    if len(sys.argv) not in (4, 6) or (len(sys.argv) == 6 and sys.argv[4] != "--screenshot"):
        print("usage: test_web.py WEBDIR BILLIARDS SAME_BITS [--screenshot FILE.png]", file=sys.stderr)
        return 2
    root, billiards, same_bits = sys.argv[1:4]
    picture = sys.argv[5] if len(sys.argv) == 6 else None
    server = serve(root)
    base = "http://127.0.0.1:%d" % server.server_port

    driver = browser(1200, 800)
    try:
        # practice on the native default rack: the hook's break against the native runs
        loaded = open_page(driver, base, "?practice")
        state = driver.execute_script("return window.collide2d && window.collide2d.state()") or {"balls": []}
        check(bool(loaded) and len(state["balls"]) == 16 and all(b["on_table"] for b in state["balls"]),
              "page loads: window.collide2d, 16 balls on the table at rest")
        ok, sizes = fills(driver)
        check(ok, "the canvas fills the window (window %dx%d, canvas %dx%d pixels)" % sizes)
        for seed, shot in ((1, (0, 12, 0, 0)), (2, (-3, 9, 0.2, -0.3))):
            if seed != 1:
                open_page(driver, base, "?practice&seed=%d" % seed)
            game, alone = native(billiards, same_bits, seed, shot)
            start = time.time()
            shot_ok = driver.execute_script("return window.collide2d.shoot(%r, %r, %r, %r)" % shot)
            rest = wait(driver, "return window.collide2d.atRest()", 120, 0.2)
            web = balls(driver.execute_script("return window.collide2d.state()"))
            print("    seed %d, shot %s: at rest after %.1f s of wall time" % (seed, shot, time.time() - start))
            check(shot_ok and rest and web == game and web == alone,
                  "seed %d, shot %s through the hook: the native headless run's positions, bit for bit" % (seed, shot))
            if web != game:
                print("    web    ", web[:3], "\n    native ", game[:3])
        check(not driver.execute_script("return window.collide2d.shoot(0, 99, 0, 0)"), "the hook refuses a shot faster than --shot allows")

        # 8-ball against the computer (the page's default): a break by mouse drag
        open_page(driver, base, "")
        canvas = driver.find_element(By.ID, "canvas")
        before = cue(driver)
        frames0, t0 = driver.execute_script("return window.collide2d.framesDrawn()"), time.time()
        time.sleep(3)
        frames1, t1 = driver.execute_script("return window.collide2d.framesDrawn()"), time.time()
        print("    frame rate at rest: %.1f frames/s drawn" % ((frames1 - frames0) / (t1 - t0)))
        chain = ActionChains(driver)
        chain.move_to_element_with_offset(canvas, 300, -60).pause(0.5).click_and_hold()
        for _ in range(8):
            chain.move_by_offset(-25, 0).pause(0.05)
        chain.release().perform()
        moving = wait(driver, "return !window.collide2d.atRest()", 30)
        frames0, t0 = driver.execute_script("return window.collide2d.framesDrawn()"), time.time()
        time.sleep(2)
        frames1, t1 = driver.execute_script("return window.collide2d.framesDrawn()"), time.time()
        print("    frame rate during the break: %.1f frames/s drawn" % ((frames1 - frames0) / (t1 - t0)))
        wait(driver, "return window.collide2d.atRest()", 120, 0.2)
        after = cue(driver)
        check(bool(moving) and before is not None and after is not None and after != before,
              "8-ball: a shot by mouse drag moves the cue ball (%s -> %s)" % (before, after))

        # the canvas is not blank: many colours, none covering nearly all of it
        data = canvas.screenshot_as_png
        width, height, pixels = png_pixels(data)
        counts = {}
        for p in pixels:
            counts[p] = counts.get(p, 0) + 1
        top = max(counts.values()) if counts else 0
        check(width > 0 and len(counts) > 100 and top < 0.9 * len(pixels),
              "canvas screenshot %dx%d is not blank (%d colours, the commonest %.0f%%)" %
              (width, height, len(counts), 100.0 * top / max(1, len(pixels))))
        if picture:
            with open(picture, "wb") as f:
                f.write(data)
            print("    wrote %s" % picture)
    finally:
        driver.quit()

    # a phone-sized window, touch only: a tap aims, a drag pulls back, the release shoots
    driver = browser(390, 844, phone=True)
    try:
        open_page(driver, base, "?practice")
        ok, sizes = fills(driver)
        check(ok, "phone-sized window: the canvas fills it (window %dx%d, canvas %dx%d pixels)" % sizes)
        rect = driver.execute_script("var r = document.getElementById('canvas').getBoundingClientRect(); return [r.width, r.height];")
        before = cue(driver)

        def touch(kind, x, y):
            points = [] if kind == "touchEnd" else [{"x": x, "y": y}]
            driver.execute_cdp_cmd("Input.dispatchTouchEvent", {"type": kind, "touchPoints": points})

        cx, cy = rect[0] * 0.8, rect[1] * 0.45  # towards the rack, right of the middle
        # the tap, then two frames drawn (the aim follows the touch at a frame's
        # start), then the drag; a phone's 1170x2532 pixels draw slowly here
        touch("touchStart", cx, cy)
        touch("touchEnd", cx, cy)
        drawn = driver.execute_script("return window.collide2d.framesDrawn()")
        wait(driver, "return window.collide2d.framesDrawn() >= %d" % (drawn + 2), 30)
        touch("touchStart", cx, cy)
        for k in range(1, 9):
            touch("touchMove", cx - 12 * k, cy)
            time.sleep(0.03)
        touch("touchEnd", cx - 96, cy)
        moving = wait(driver, "return !window.collide2d.atRest()", 30, 0.02)
        after = cue(driver)  # at once: a scratch would put it back on its spot at rest
        wait(driver, "return window.collide2d.atRest()", 120, 0.2)
        # the first aim follows the mouse's (0, 0), up and to the left: a shot
        # towards +x (the rack) went where the tap aimed
        check(bool(moving) and after is not None and after[0] > before[0],
              "phone-sized window: a tap aims, a drag shoots: the cue ball goes towards the tap (%s -> %s)" % (before, after))
    finally:
        driver.quit()
    server.shutdown()
    print("test_web: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
