"""Reads the audio of report.html back (tests/e2e/report_page_test.cpp): every data:audio/wav source is
decoded with Python's wave module. Prints a JSON list: per player its title, rate, sample width,
channels and frames.

Usage: report_page_test.py report.html
"""
import base64
import html.parser
import io
import json
import sys
import wave


class Players(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.found = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "audio" and a.get("src", "").startswith("data:audio/wav;base64,"):
            with wave.open(io.BytesIO(base64.b64decode(a["src"].split(",", 1)[1]))) as w:
                self.found.append({"title": a.get("title"), "rate": w.getframerate(), "width": w.getsampwidth(),
                                   "channels": w.getnchannels(), "frames": w.getnframes()})


parser = Players()
parser.feed(open(sys.argv[1], encoding="utf-8").read())
print(json.dumps(parser.found))
