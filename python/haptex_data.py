"""Moved to the package: haptex.data (python/haptex/data.py; `import haptex` gives its readers and
write_predictions too). `import haptex_data` still works and is that very module, so
haptex_data.read_split, haptex_data.WindowDataset and the rest are unchanged."""
import sys

import haptex.data

sys.modules[__name__] = haptex.data
