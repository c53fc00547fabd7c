"""The ``[sweep]`` capability (:mod:`.stage`): one quantity over its values, evaluated as one population of
designs (:mod:`.population`) or design by design through the file's other tables (:mod:`.runs`); several
quantities are an exploration (:mod:`machdyn.studies.exploration`)."""

__all__: list[str] = []
