"""simhuman's policy files in PyTorch (Debian's python3-torch, the same 1.13 as our LibTorch).

A policy file (assets/policies/walk.pt, written by ``simhuman export-policy`` or a training
checkpoint) is a LibTorch archive; ``torch.jit.load`` reads it. ``load_policy`` rebuilds the
Gaussian MLP actor and the observation normalizer from it as an ordinary ``torch.nn.Module``,
so it can drive ``simhuman.vector`` envs, be fine-tuned, or be inspected:

    policy = simhuman.policy.load_policy("assets/policies/walk.pt")
    actions = policy.act(obs)   # numpy [num_envs, obs_dim] -> numpy float32 [num_envs, act_dim]
"""

import numpy as np
import torch

POLICY_FORMAT = "simhuman-policy-v1"


class GaussianPolicy(torch.nn.Module):
    """A diagonal Gaussian policy: mean = MLP(normalized obs), state-independent log std.

    The layout is the C++ one (control/policy/policy_net.h): Linear+ELU hidden layers, a linear
    output, observations normalized by running mean and variance and clipped to +-obs_clip.
    """

    def __init__(self, obs_dim, act_dim, hidden, obs_clip=5.0, init_std=0.5):
        super().__init__()
        layers, width = [], obs_dim
        for h in hidden:
            layers += [torch.nn.Linear(width, h), torch.nn.ELU()]
            width = h
        layers.append(torch.nn.Linear(width, act_dim))
        self.net = torch.nn.Sequential(*layers)
        self.log_std = torch.nn.Parameter(torch.full((act_dim,), float(np.log(init_std))))
        self.register_buffer("obs_mean", torch.zeros(obs_dim, dtype=torch.float64))
        self.register_buffer("obs_var", torch.ones(obs_dim, dtype=torch.float64))
        self.obs_clip = float(obs_clip)
        self.task = ""
        self.walk_gait = ""  # the reference gait a walk policy was trained with ("" or "human")

    def normalize(self, obs):
        """(obs - mean) / sqrt(var + 1e-8), clipped to +-obs_clip (float32)."""
        std = torch.sqrt(self.obs_var + 1e-8).float()
        return torch.clamp((obs - self.obs_mean.float()) / std, -self.obs_clip, self.obs_clip)

    def forward(self, obs):
        """Mean action for raw observations [B, obs_dim] (float32 tensor)."""
        return self.net(self.normalize(obs))

    def std(self):
        """Action standard deviation [act_dim], clamped to [0.05, 1] as in C++."""
        return torch.exp(torch.clamp(self.log_std, float(np.log(0.05)), 0.0))

    @torch.no_grad()
    def act(self, obs):
        """Deterministic (mean) actions for a numpy batch of observations, as numpy float32."""
        return self.forward(torch.as_tensor(np.asarray(obs, dtype=np.float32))).numpy()


def load_policy(path):
    """The policy in a simhuman policy file or checkpoint, as a GaussianPolicy (eval mode).

    Raises ValueError naming the file when it is not a simhuman policy archive."""
    try:
        archive = torch.jit.load(str(path), map_location="cpu")
    except (RuntimeError, ValueError) as e:
        raise ValueError(f"{path}: not a simhuman policy file ({e})") from None
    fmt = getattr(archive, "format", None)
    if fmt != POLICY_FORMAT:
        raise ValueError(f"{path}: format {fmt!r} is not {POLICY_FORMAT!r}")
    hidden = [int(h) for h in archive.hidden.tolist()]
    policy = GaussianPolicy(int(archive.obs_dim), int(archive.act_dim), hidden,
                            float(archive.obs_clip))
    policy.task = str(archive.task)
    policy.walk_gait = str(getattr(archive, "variant", ""))
    params = dict(archive.actor.named_parameters())
    state = {"log_std": params["log_std"], "obs_mean": archive.obs_mean,
             "obs_var": archive.obs_var}
    linear = [i for i, m in enumerate(policy.net) if isinstance(m, torch.nn.Linear)]
    for i in linear:
        state[f"net.{i}.weight"] = params[f"net.{i}.weight"]
        state[f"net.{i}.bias"] = params[f"net.{i}.bias"]
    policy.load_state_dict({k: v.detach().clone() for k, v in state.items()})
    return policy.eval()
