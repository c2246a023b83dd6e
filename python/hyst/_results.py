"""Named results of hyst's fits."""

import html

from . import _core


class FitResult(tuple):
    """What a fit returns: the fitted `model`, the `state` it starts from and the fit `report`.

    It is the tuple the fit returned before, so `model, report = hyst.fit(...)` (and `model,
    state, report = hyst.fit_prandtl_ishlinskii(...)`) unpack as they always did. For the
    registry's fits the state is the model file's state, `model.state`. The fits with measured
    polarisation return further reports after the model's (`report` is the model's own).
    """

    __slots__ = ()

    @property
    def model(self):
        return self[0]

    @property
    def state(self):
        return self[1] if len(self) == 3 and not self._reports_second() else self[0].state

    @property
    def report(self):
        # (model, report, ...more reports) or (model, state, report)
        return self[1] if self._reports_second() else self[-1]

    def _reports_second(self):
        return isinstance(self[1], _core.FitReport)

    def _rows(self):
        report = self.report
        name = getattr(self.model, "name", type(self.model).__name__)
        rows = [("model", name), ("method", report.method), ("status", report.status),
                ("iterations", report.iterations), ("parameters", report.parameters),
                ("fit NRMSE [%]", f"{report.fit.nrmse_percent:.4g}")]
        if report.validation is not None:
            rows.append(("validation NRMSE [%]", f"{report.validation.nrmse_percent:.4g}"))
        rows.append(("fit time [s]", f"{report.seconds:.3g}"))
        return rows

    def __repr__(self):
        fields = ", ".join(f"{key}={value}" for key, value in self._rows())
        return f"FitResult({fields})"

    def _repr_html_(self):
        cells = "".join(f"<tr><th style='text-align:left'>{html.escape(str(key))}</th>"
                        f"<td>{html.escape(str(value))}</td></tr>" for key, value in self._rows())
        return (f"<table>{cells}</table><details><summary>fit report</summary>"
                f"<pre>{html.escape(self.report.full())}</pre></details>")
