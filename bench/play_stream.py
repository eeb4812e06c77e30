"""haptex play fed a live stream: 10 s of `force speed` lines at 1 kHz on standard input, played on
ALSA's file plugin over its null plugin (no sound card needed; haptex's clock paces it as a card would).
Prints haptex play's --json report: latency from a line to the device (median, 99th percentile),
underruns, late periods, the slowest frame and the CPU share of one core, for online and noise.

Usage: play_stream.py HAPTEX MODEL   (run_bench.sh runs it, and haptex, on one core)
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import time

haptex, model = sys.argv[1], sys.argv[2]
material = json.loads(subprocess.run([haptex, "--json", "info", model], capture_output=True, check=True).stdout)["materials"][0]["id"]
results = {}
with tempfile.TemporaryDirectory() as folder:
    conf = os.path.join(folder, "asound.conf")
    with open(conf, "w") as f:
        f.write('pcm.nothing { type null }\npcm.capture { type file; slave { pcm "nothing" } file "%s" format "raw" }\n'
                % os.path.join(folder, "played.raw"))
    env = dict(os.environ, ALSA_CONFIG_PATH=conf)
    for method in ("online", "noise"):
        play = subprocess.Popen([haptex, "--json", "play", model, "--material", material, "--actions", "-", "--device", "capture",
                                 "--reconstruct", method], stdin=subprocess.PIPE, stdout=subprocess.PIPE, env=env, text=True)
        time.sleep(0.5)  # its start-up: lines sent meanwhile would all arrive at once
        start = time.monotonic()
        for i in range(10000):
            while time.monotonic() < start + i / 1000:
                time.sleep(0.0002)
            play.stdin.write("%.4f %.3f\n" % (1.2 + 0.6 * math.sin(i / 190), 120 + 80 * math.sin(i / 330)))
            play.stdin.flush()
        play.stdin.close()
        results[method] = json.loads(play.stdout.read())
        play.wait()
print(json.dumps(results))
