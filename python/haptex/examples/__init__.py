"""Worked examples whose predictions `haptex evaluate --predictions` scores (python/README.md):

    python3 -m haptex.examples.knn_baseline dataset.h5 split.json windows.h5 -o knn.h5
    python3 -m haptex.examples.torch_mlp dataset.h5 split.json windows.h5 -o mlp.h5   # needs python3-torch
"""
