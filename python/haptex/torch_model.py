"""A haptex model file as a torch module with the outputs of `haptex predict`.

    import haptex.torch_model
    net = haptex.torch_model.load("model.h5")               # eval mode, float32, on the CPU
    spectra = net(actions, material=torch.tensor([0, 0]))   # actions (N, 20): 10 forces in N, 10 speeds in mm/s
    spectra = net(actions, latent=latents)                  # unified: (N, L) or (L,) latents, e.g. a press's
    latent = net.recognised(net.image_latent(descriptor))   # a press's descriptor (haptex.press_latent) -> its latent

The forward pass is schemas/hdf5-layout.md's ("Model file"), as haptex.model runs it in numpy:
saturate the action into the training range (a non-finite value becomes the training mean),
standardise, the action encoder, then the predictor on [latent, code], times the per-bin scale. The
module is differentiable in the action and the latent; its weights are parameters, so it can be
fine-tuned, but a model changed in torch is not written back to a haptex model file.

Needs PyTorch (Debian: apt-get install python3-torch); without it importing this module raises
ImportError saying so.
"""
try:
    import torch
    from torch import nn
except Exception as e:  # noqa: BLE001 - absent, or installed but broken (OSError, RuntimeError: review 14, F7)
    raise ImportError("haptex.torch_model needs PyTorch, which this Python cannot import "
                      f"({type(e).__name__}: {e}): install python3-torch "
                      "(Debian: apt-get install python3-torch) or `pip install torch` in a virtual environment") from None

import numpy as np

from .model import read_model


def _sequential(layers, dtype):
    modules = []
    for layer in layers:
        linear = nn.Linear(layer.weight.shape[1], layer.weight.shape[0])
        with torch.no_grad():
            linear.weight.copy_(torch.from_numpy(np.asarray(layer.weight)))
            linear.bias.copy_(torch.from_numpy(np.asarray(layer.bias)))
        modules.append(linear)
        if layer.activation == "relu":
            modules.append(nn.ReLU())
        elif layer.activation == "softplus":
            modules.append(nn.Softplus())
    return nn.Sequential(*modules).to(dtype)


class HaptexModel(nn.Module):
    """A haptex model: `forward(actions, material=None, latent=None)` -> spectra (N, 100) in m/s^2 at
    10, 20, ..., 1000 Hz. `ids` are the materials' ids (an index into them is a material);
    `variant` is "unified" or "per-material"."""

    def __init__(self, model, dtype=torch.float32):
        super().__init__()
        self.path, self.variant, self.ids = model.path, model.variant, list(model.ids)
        as_tensor = lambda a: torch.as_tensor(np.asarray(a, dtype=np.float32)).to(dtype)
        for name in ("action_mean", "action_scale", "target_scale", "low", "high"):
            self.register_buffer(name, as_tensor(getattr(model, name)))
        self.nets = nn.ModuleList(nn.ModuleDict({"action_encoder": _sequential(n.action_encoder, dtype),
                                                 "predictor": _sequential(n.predictor, dtype)}) for n in model.nets)
        if model.variant == "unified":
            self.register_buffer("descriptor_mean", as_tensor(model.descriptor_mean))
            self.register_buffer("descriptor_scale", as_tensor(model.descriptor_scale))
            self.register_buffer("material_latents", as_tensor(model.material_latents))
            self.texture_encoder = _sequential(model.texture_encoder, dtype)
            self.classifier = _sequential(model.classifier, dtype)

    def material_index(self, material_id):
        if material_id not in self.ids:
            raise ValueError(f"{self.path}: no material '{material_id}'; the model knows {', '.join(self.ids)}")
        return self.ids.index(material_id)

    def saturate(self, actions):
        """(saturated actions, per action whether anything changed): `haptex predict`'s out_of_range."""
        v = torch.where(torch.isfinite(actions), actions, self.action_mean.expand_as(actions))
        v = torch.minimum(torch.maximum(v, self.low), self.high)
        return v, (v != actions).any(dim=-1)

    def image_latent(self, descriptor):
        """The texture encoder's output for descriptors (D,) or (N, D)."""
        self._need_unified()
        return self.texture_encoder((torch.as_tensor(descriptor, dtype=self.action_mean.dtype) - self.descriptor_mean)
                                    / self.descriptor_scale)

    def recognised(self, image_latent):
        """The latent the predictor sees for a press: the materials' latents weighted by the
        classifier's softmax (docs/predict.md, "A new press")."""
        self._need_unified()
        return torch.softmax(self.classifier(image_latent), dim=-1) @ self.material_latents

    def forward(self, actions, material=None, latent=None):
        actions = torch.as_tensor(actions, dtype=self.action_mean.dtype)
        single = actions.dim() == 1
        actions = actions.reshape(-1, actions.shape[-1])
        x = (self.saturate(actions)[0] - self.action_mean) / self.action_scale
        if isinstance(material, str):
            material = self.material_index(material)
        if self.variant == "unified":
            if (material is None) == (latent is None):
                raise ValueError("give a material (index or id) or a latent")
            if latent is None:
                latent = self.material_latents[torch.as_tensor(material)]
            latent = torch.as_tensor(latent, dtype=x.dtype).expand(len(x), self.material_latents.shape[1])
            net = self.nets[0]
            out = net["predictor"](torch.cat([latent, net["action_encoder"](x)], dim=1))
        else:
            if material is None or latent is not None:
                raise ValueError("a per-material model needs a material (index or id) and has no latent")
            index = torch.as_tensor(material).expand(len(x))
            out = x.new_zeros(len(x), self.target_scale.shape[0])
            for k in torch.unique(index).tolist():
                rows = index == k
                net = self.nets[k]
                out[rows] = net["predictor"](net["action_encoder"](x[rows]))
        out = self.target_scale * out
        return out[0] if single else out

    def _need_unified(self):
        if self.variant != "unified":
            raise ValueError(f"{self.path}: a per-material model has no texture encoder; choose a material")


def load(model_path, dtype=torch.float32):
    """model.h5 (haptex train) as a HaptexModel in eval mode; refuses a damaged file as
    haptex.read_model does (HaptexFileError)."""
    return HaptexModel(read_model(model_path), dtype).eval()
