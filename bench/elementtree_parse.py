"""The HaTT XML parse a user would otherwise write: xml.etree.ElementTree and numpy, on the 10 s
recording `bench_convert --export-xml FILE` writes (the file BM_ParseHattXml_10s parses). Every array
element (<accelX type="array">, ...) becomes a float64 numpy array of its <value> children. Best of 3
rounds of CPU time; prints JSON {"seconds", "megabytes_per_second", "python", "samples"}.

Usage: /usr/bin/python3 bench/elementtree_parse.py RECORDING.xml
"""
import json
import os
import platform
import sys
import time
import xml.etree.ElementTree as ElementTree

import numpy as np


def parse(path):
    root = ElementTree.parse(path).getroot()
    return {child.tag: np.array([float(v.text) for v in child.iter("value")])
            for child in root if child.get("type") == "array"}


def main():
    path = sys.argv[1]
    best, channels = float("inf"), {}
    for _ in range(3):
        start = time.process_time()
        channels = parse(path)
        best = min(best, time.process_time() - start)
    print(json.dumps({"seconds": best, "megabytes_per_second": os.path.getsize(path) / best / 1e6,
                      "python": platform.python_version(), "samples": sum(len(v) for v in channels.values())}))


if __name__ == "__main__":
    main()
