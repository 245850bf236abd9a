"""The benchmarks' runner without the executable: the Python module renders
in this process, as `caustica render` would (the same job), so a run
costs no process start and no scene parse after the first, and a compare
reads neither the render nor the reference back from disk. Each render
still writes its EXR, for inspection and for the scripts that read the
variance layers."""

import importlib
import sys
from pathlib import Path

from caustica_cli import Caustica, SceneRefused, UnknownIntegrator


def _module(binary):
    """The module the build of `binary` made (build/python beside build/caustica), or None."""
    folder = Path(binary).resolve().parent / "python"
    if not any(folder.glob("caustica*.so")):
        return None
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))
    return importlib.import_module("caustica")


class InProcessCaustica:
    def __init__(self, module, threads):
        self.caustica = module
        self.threads = threads
        self._scenes = {}
        self._renders = {}  # output path -> result, so compare need not read it back
        self._references = {}  # path -> (modification time, result)

    def _scene(self, path, defines):
        key = (str(path), tuple(sorted(defines.items())))
        if key not in self._scenes:
            self._scenes[key] = self.caustica.load(path, defines=defines)
        return self._scenes[key]

    def render(self, scene, output, *, integrator, spp, seed, res, options=()):
        """As Caustica.render: the scene takes `independent` unless the integrator names a sampler after '@';
        options may be --spectral on|off|auto and --light-selection tree|power|auto."""
        name, _, sampler = integrator.partition("@")
        defines = {"res": str(res), "sampler": sampler or "independent"}
        if sampler:
            defines["spp"] = str(spp)
        options = list(map(str, options))
        settings = {"--spectral": "auto", "--light-selection": "auto"}
        if len(options) % 2 or any(flag not in settings for flag in options[::2]):
            raise ValueError(f"the in-process runner takes only --spectral and --light-selection, not {options}")
        settings.update(zip(options[::2], options[1::2]))
        try:
            result = self.caustica.render(self._scene(scene, defines), integrator=name, spp=spp, seed=seed,
                                          threads=self.threads, spectral=settings["--spectral"],
                                          light_selection=settings["--light-selection"])
        except ValueError as error:
            if "unknown integrator" in str(error):
                raise UnknownIntegrator(str(error)) from error
            if "does not render" in str(error):
                raise SceneRefused(str(error)) from error
            raise
        result.write(output)
        self._renders[str(output)] = result
        return _without_prefix(result.metadata)

    def merge(self, inputs, output):
        merged = self.caustica.merge([self._renders.get(str(path), str(path)) for path in inputs])
        merged.write(output)
        self._renders[str(output)] = merged
        return _without_prefix(merged.metadata)

    def compare(self, image, reference):
        return self.caustica.compare(self._renders.get(str(image), str(image)), self._reference(reference))

    def _reference(self, path):
        stamp = Path(path).stat().st_mtime_ns
        cached = self._references.get(str(path))
        if cached is None or cached[0] != stamp:
            cached = (stamp, self._renders.get(str(path)) or self.caustica.read(path))
            self._references[str(path)] = cached
        return cached[1]


def _without_prefix(metadata):
    return {key.split(":", 1)[1]: value for key, value in metadata.items() if key.startswith("caustica:")}


def runner(binary, threads):
    """The module's in-process runner where the build of `binary` made the module, else the executable."""
    module = _module(binary)
    return InProcessCaustica(module, threads) if module else Caustica(binary, threads)
