"""The exceptions rattleback raises."""


class SceneError(ValueError):
    """A scene (a file, a YAML string, a dict or a value put in with ``with_values``) that
    cannot be used, with the same one-line message as the command line.

    Attributes:
        file: the scene file, or where the value came from (``"with_values"``,
            ``"argument dt"``, ``"<dict>"``).
        line: the 1-based line in ``file``, or ``None`` when not in a file.
        key: the dotted scene key concerned (``"contact.friction"``), or ``None``.
    """

    def __init__(self, message, file=None, line=None, key=None):
        super().__init__(message)
        self.file = file
        self.line = line
        self.key = key


class RunWarning(UserWarning):
    """What ``rattleback simulate``'s summary warns of, issued by :func:`simulate` with
    :func:`warnings.warn` (a notebook shows it under the cell): the step too large for a model
    that keeps the energy, a mass no material gives the body, a spin that ended the other way
    with no reversal counted, …. Each is also in ``run.result["warnings"]`` as ``{code, text}``.

    Attributes:
        code: ``"energy_error"``, ``"implausible_mass"``, ``"sign_changed_uncounted"``, ….
    """

    def __init__(self, message, code=None):
        super().__init__(message)
        self.code = code


class RunStopped(RuntimeError):
    """A run that stopped by itself before its end (the command line's exit status 3).

    Attributes:
        reason: ``"non_finite"``, ``"energy_gain"`` or ``"on_rim"``.
        t: the simulated time it stopped at, s.
        step: the step it stopped at.
        run: the :class:`Run` as far as it went (its samples up to the stop, its ``result``
            with ``status`` ``"stopped"``), to plot what led there; ``None`` where there is
            none.
    """

    def __init__(self, message, reason=None, t=None, step=None, run=None):
        super().__init__(message)
        self.reason = reason
        self.t = t
        self.step = step
        self.run = run
