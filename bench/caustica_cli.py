"""The caustica executable as the benchmarks call it: render, merge, compare."""

import subprocess

import OpenImageIO as oiio


class UnknownIntegrator(Exception):
    """The binary has no integrator of that name (it may not have landed yet)."""


class SceneRefused(Exception):
    """The integrator cannot render this scene (media, for one that does not render them yet)."""


class Caustica:
    def __init__(self, binary, threads, launcher=(), env=None):
        """`launcher` prefixes each command (mpirun -n 2, for a render across ranks)."""
        self.binary = str(binary)
        self.threads = threads
        self.launcher = list(launcher)
        self.env = env

    def _run(self, args):
        result = subprocess.run([*self.launcher, self.binary, *map(str, args)], capture_output=True, text=True,
                                env=self.env)
        if result.returncode != 0:
            message = result.stderr.strip() or result.stdout.strip()
            if "unknown integrator" in message:
                raise UnknownIntegrator(message)
            if "does not render" in message:
                raise SceneRefused(message)
            raise RuntimeError(f"caustica {args[0]} failed: {message}")
        return result.stdout

    def render(self, scene, output, *, integrator, spp, seed, res, options=()):
        """Renders a float EXR (and its PNG); returns the EXR's metadata.

        `integrator` may name a sampler after an '@' (path@ldsampler), which the scene takes as $sampler, with
        its sample_count ($spp) the run's: the stratifying samplers stratify the whole run, not blocks of it.
        Without one the scene gets `independent`, whatever its own default: references, merges and the
        variance layers assume independent samples. `options` go to the command line as they are
        (--spectral on).
        """
        name, _, sampler = integrator.partition("@")
        defines = ["-D", f"res={res}"] + (["-D", f"sampler={sampler}", "-D", f"spp={spp}"]
                                          if sampler else ["-D", "sampler=independent"])
        self._run(["render", scene, "-o", output, "--integrator", name, "--spp", spp, "--seed", seed, *defines,
                   "--threads", self.threads, "--exr-format", "float", "-q", *options])
        return read_metadata(output)

    def merge(self, inputs, output):
        """Merges independent renders; returns the merged EXR's metadata."""
        self._run(["merge", *inputs, "-o", output])
        return read_metadata(output)

    def compare(self, image, reference):
        """The error metrics of `image` against `reference`, by name (see caustica compare)."""
        out = self._run(["compare", image, reference])
        return {name: float(value) for name, value in (line.split() for line in out.splitlines())}


def _spec(path):
    image = oiio.ImageInput.open(str(path))
    if image is None:
        raise RuntimeError(f"cannot read {path}: {oiio.geterror()}")
    spec = image.spec()
    image.close()
    return spec


def image_size(path):
    spec = _spec(path)
    return spec.width, spec.height


def read_metadata(path):
    """An EXR's caustica:* metadata, without the prefix."""
    spec = _spec(path)
    return {a.name.split(":", 1)[1]: a.value for a in spec.extra_attribs if a.name.startswith("caustica:")}
