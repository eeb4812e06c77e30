"""A haptex model file (`haptex train`'s model.h5) read with h5py and run in numpy, as `haptex predict`
runs it: schemas/hdf5-layout.md ("Model file") spells out the layout and the forward pass, which
`Model` follows step by step; haptex.torch_model makes the same network a torch module.

    model = haptex.read_model("model.h5")
    spectra, out_of_range = model.spectrum(actions, material="cork")  # actions: (N, 20) or (20,)
    latent = model.recognised(model.image_latent(descriptor))          # a press's latent (unified)
    spectra, _ = model.spectrum(actions, latent=latent)

The descriptor of an image is computed by haptex itself (predict/texture_descriptor.cpp):
haptex.press_latent(model_path, image) runs `haptex predict --json` and returns it.
"""
from dataclasses import dataclass, field

import h5py
import numpy as np

from .data import ACTION_SAMPLES, TARGET_BINS, HaptexFileError, _attribute, _text, open_hdf5, require_plain_objects, strict_json

FORMAT = "model/3"
ACTIVATIONS = ("linear", "relu", "softplus")


@dataclass
class Layer:
    """activation(weight @ x + bias): weight (outputs, inputs) and bias (outputs), float32."""
    weight: np.ndarray
    bias: np.ndarray
    activation: str


@dataclass
class Net:
    """One action encoder and predictor (/nets/{k}): the unified model has one, a per-material model
    one per material, in the order of `Model.ids`."""
    action_encoder: list
    predictor: list


@dataclass
class Model:
    path: str
    variant: str                 # "unified" or "per-material"
    ids: list                    # material ids, /materials/ids
    names: list
    action_mean: np.ndarray      # (20,) float32
    action_scale: np.ndarray     # (20,)
    target_scale: np.ndarray     # (100,)
    low: np.ndarray              # (20,) float32: force_min ten times, then speed_min ten times
    high: np.ndarray             # (20,)
    nets: list
    descriptor_mean: np.ndarray = None   # unified only, (D,)
    descriptor_scale: np.ndarray = None
    texture_encoder: list = field(default_factory=list)
    classifier: list = field(default_factory=list)
    material_latents: np.ndarray = None  # (K, L)
    config: dict = field(default_factory=dict)
    metrics: dict = field(default_factory=dict)
    dataset_sha256: str = ""
    split_sha256: str = ""

    def material_index(self, material):
        """The index of a material id (or an index given as an int)."""
        if isinstance(material, (int, np.integer)) and not isinstance(material, bool):
            if not 0 <= material < len(self.ids):
                raise ValueError(f"{self.path}: no material {material} (the model has {len(self.ids)})")
            return int(material)
        if material not in self.ids:
            raise ValueError(f"{self.path}: no material '{material}'; the model knows {', '.join(self.ids)}")
        return self.ids.index(material)

    def saturated(self, actions):
        """Step 1: each action's values with a non-finite value replaced by the training mean and
        clamped into the training range, in float32, and per action whether anything changed
        (`haptex predict`'s out_of_range)."""
        a = np.asarray(actions, dtype=np.float32)
        v = np.where(np.isfinite(a), a, self.action_mean)
        v = np.minimum(np.maximum(v, self.low), self.high)
        with np.errstate(invalid="ignore"):
            return v, np.any(v != a, axis=-1)

    def image_latent(self, descriptor):
        """The texture encoder's output for a press's descriptor (unified models)."""
        self._need_unified("an image's latent")
        d = np.asarray(descriptor, dtype=np.float64)
        if d.shape[-1:] != self.descriptor_mean.shape:
            raise ValueError(f"{self.path}: a descriptor of {d.shape[-1:]} values, the model expects {self.descriptor_mean.size}")
        return run(self.texture_encoder, (d - self.descriptor_mean) / self.descriptor_scale)

    def recognised(self, image_latent):
        """The latent the predictor sees for a press (docs/predict.md, "A new press"): the materials'
        latents weighted by softmax(classifier(image_latent))."""
        self._need_unified("recognition")
        logits = run(self.classifier, np.asarray(image_latent, dtype=np.float64))
        p = np.exp(logits - logits.max(axis=-1, keepdims=True))
        return (p / p.sum(axis=-1, keepdims=True)) @ self.material_latents.astype(np.float64)

    def spectrum(self, actions, material=None, latent=None):
        """Spectra (N, 100) in m/s^2 at 10..1000 Hz for actions (N, 20) (or one (20,) action: (100,)),
        for a training material (its id or index) or, unified, a latent (L,) or (N, L); and per action
        whether it was saturated. Computed in float64 from the float32 weights."""
        a = np.asarray(actions, dtype=np.float32)
        single = a.ndim == 1
        a = np.atleast_2d(a)
        if a.shape[-1] != 2 * ACTION_SAMPLES:
            raise ValueError(f"an action is {2 * ACTION_SAMPLES} values (10 forces in N, 10 speeds in mm/s), not {a.shape[-1]}")
        v, out_of_range = self.saturated(a)
        net = 0
        if self.variant == "unified":
            if (material is None) == (latent is None):
                raise ValueError("give a material or a latent")
            if latent is None:
                latent = self.material_latents[self.material_index(material)]
            latent = np.broadcast_to(np.asarray(latent, dtype=np.float64), (len(a), self.material_latents.shape[1]))
        else:
            if material is None or latent is not None:
                raise ValueError("a per-material model needs a material (it has no latent)")
            net = self.material_index(material)
            latent = np.zeros((len(a), 0))
        x = (v.astype(np.float64) - self.action_mean) / self.action_scale
        code = run(self.nets[net].action_encoder, x)
        out = self.target_scale * run(self.nets[net].predictor, np.concatenate([latent, code], axis=1))
        return (out[0], bool(out_of_range[0])) if single else (out, out_of_range)

    def _need_unified(self, what):
        if self.variant != "unified":
            raise ValueError(f"{self.path}: a per-material model has no texture encoder, so no {what}; choose a material")


def run(layers, x):
    """Layers applied in order to x (a vector, or one row per input), in float64."""
    x = np.asarray(x, dtype=np.float64)
    for layer in layers:
        z = x @ layer.weight.T.astype(np.float64) + layer.bias
        if layer.activation == "relu":
            x = np.maximum(z, 0.0)
        elif layer.activation == "softplus":
            x = np.logaddexp(0.0, z)  # log(1 + e^z)
        else:
            x = z
    return x


class _Reader:
    def __init__(self, f, path):
        self.f, self.path = f, path

    def fail(self, where, what):
        raise HaptexFileError(f"{self.path}: {where}: {what}. Train the model again (haptex train)")

    def array(self, name, shape=None, positive=False):
        if name not in self.f:
            self.fail("/" + name, "is missing")
        d = self.f[name]
        if not isinstance(d, h5py.Dataset) or d.dtype != np.float32:
            self.fail(d.name, "must be a float32 array")
        if shape is not None and d.shape != shape:
            self.fail(d.name, f"has shape {d.shape}, expected {shape}")
        a = d[()]
        if not np.all(np.isfinite(a)):
            self.fail(d.name, "holds NaN or infinity")
        if positive and not np.all(a >= np.finfo(np.float32).tiny):
            self.fail(d.name, "holds a scale that is not a positive normal float32 (at least 1.2e-38)")
        return a

    def attr(self, obj, name):
        value = _attribute(obj, name, self.path, None)
        if value is None:
            self.fail(f"{obj.name}@{name}", "is missing")
        return value

    def layers(self, name, inputs):
        """GROUP/layers/0, 1, ...; each layer's inputs must be the previous one's outputs."""
        if name + "/layers" not in self.f:
            self.fail(f"/{name}/layers", "is missing")
        g = self.f[name + "/layers"]
        if len(g) == 0 or sorted(g.keys()) != sorted(str(i) for i in range(len(g))):
            self.fail(g.name, f"expected layers numbered 0, 1, ...; found {sorted(g.keys())}")
        out = []
        for i in range(len(g)):
            weight = self.array(f"{name}/layers/{i}/weight")
            if weight.ndim != 2 or (inputs is not None and weight.shape[1] != inputs):
                self.fail(f"/{name}/layers/{i}/weight", f"has shape {weight.shape}, expected ({weight.shape[0] if weight.ndim else '?'}, {inputs})")
            bias = self.array(f"{name}/layers/{i}/bias", (weight.shape[0],))
            activation = _text(self.attr(g[str(i)], "activation"))
            if activation not in ACTIVATIONS:
                self.fail(f"/{name}/layers/{i}@activation", f"is '{activation}', not linear, relu or softplus")
            out.append(Layer(weight, bias, activation))
            inputs = weight.shape[0]
        return out


def _ascii_id(name):
    """A name's material id (core/naming.hpp) for an ASCII name: lower-case letters and digits, one '_'
    between words. None for a name beyond ASCII, whose id haptex's own reader checks."""
    if not name.isascii():
        return None
    words, word = [], ""
    for c in name:
        if c.isalnum():
            word += c.lower()
        elif word:
            words.append(word)
            word = ""
    return "_".join(words + ([word] if word else []))


def _check_ids(r, ids, names):
    """As haptex's model reader: as many names as ids, each id its name's, none twice or empty
    (review 19 F2, review 20 F2)."""
    if not ids or len(names) != len(ids):
        r.fail("/materials", f"{len(ids)} ids and {len(names)} names")
    for i, (id_, name) in enumerate(zip(ids, names)):
        if not id_ or "\0" in name or _ascii_id(name) not in (None, id_):
            r.fail(f"/materials/ids[{i}]", f"'{id_}' is not the id of the material's name '{name}' (names[{i}])")
    if len(set(ids)) != len(ids):
        r.fail("/materials/ids", "names one material twice")


def read_model(path):
    """A model file, every array checked as haptex's reader checks it (float32, shapes, finite,
    positive scales); raises HaptexFileError naming the file and the object otherwise."""
    with open_hdf5(path) as f:
        r = _Reader(f, path)
        found = _text(_attribute(f, "haptex_format", path, ""))
        if found != FORMAT:
            raise HaptexFileError(f"{path}: /@haptex_format is '{found}', not {FORMAT} (haptex train writes it)")
        variant = _text(r.attr(f, "variant"))
        if variant not in ("unified", "per-material"):
            r.fail("/@variant", f"is '{variant}', not unified or per-material")
        require_plain_objects(f, path)
        ids = [_text(s) for s in f["materials/ids"][()]] if "materials/ids" in f else r.fail("/materials/ids", "is missing")
        names = [_text(s) for s in f["materials/names"][()]] if "materials/names" in f else r.fail("/materials/names", "is missing")
        _check_ids(r, ids, names)
        n = f["normalisation"] if "normalisation" in f else r.fail("/normalisation", "is missing")
        try:
            bounds = [np.float32(float(r.attr(n, k))) for k in ("force_min", "force_max", "speed_min", "speed_max")]
        except (TypeError, ValueError):
            r.fail("/normalisation", "force_min, force_max, speed_min and speed_max must be one number each")
        if not all(np.isfinite(bounds)) or bounds[0] > bounds[1] or bounds[2] > bounds[3]:
            r.fail("/normalisation", f"force and speed ranges {bounds} are not finite and ordered")
        half = ACTION_SAMPLES
        m = Model(path=path, variant=variant, ids=ids, names=names,
                  action_mean=r.array("normalisation/action_mean", (2 * half,)),
                  action_scale=r.array("normalisation/action_scale", (2 * half,), positive=True),
                  target_scale=r.array("normalisation/target_scale", (TARGET_BINS,), positive=True),
                  low=np.repeat(np.float32([bounds[0], bounds[2]]), half), high=np.repeat(np.float32([bounds[1], bounds[3]]), half),
                  nets=[], dataset_sha256=_text(_attribute(f, "dataset_sha256", path, "")),
                  split_sha256=_text(_attribute(f, "split_sha256", path, "")))
        for name in ("config", "metrics"):
            setattr(m, name, strict_json(_text(_attribute(f, name, path, "{}")), f"{path}: /@{name}"))
        latent = 0
        if variant == "unified":
            if "feature_spec" not in f:
                r.fail("/feature_spec", "is missing")
            try:
                length = int(r.attr(f["feature_spec"], "length"))
            except (TypeError, ValueError, OverflowError):
                r.fail("/feature_spec@length", "must be one whole number")
            m.descriptor_mean = r.array("normalisation/descriptor_mean", (length,))
            m.descriptor_scale = r.array("normalisation/descriptor_scale", (length,), positive=True)
            m.texture_encoder = r.layers("texture_encoder", length)
            latent = m.texture_encoder[-1].weight.shape[0]
            m.classifier = r.layers("classifier", latent)
            if m.classifier[-1].weight.shape[0] != len(ids):
                r.fail("/classifier", f"ends in {m.classifier[-1].weight.shape[0]} outputs for {len(ids)} materials")
            m.material_latents = r.array("material_latents", (len(ids), latent))
        count = 1 if variant == "unified" else len(ids)
        if "nets" not in f or len(f["nets"]) != count:
            r.fail("/nets", f"must hold {count} network(s)")
        for k in range(count):
            encoder = r.layers(f"nets/{k}/action_encoder", 2 * half)
            predictor = r.layers(f"nets/{k}/predictor", latent + encoder[-1].weight.shape[0])
            if predictor[-1].weight.shape[0] != TARGET_BINS:
                r.fail(f"/nets/{k}/predictor", f"ends in {predictor[-1].weight.shape[0]} outputs, not {TARGET_BINS}")
            m.nets.append(Net(encoder, predictor))
    return m
