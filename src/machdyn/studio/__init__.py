"""``machdyn studio``: a local web page that edits a linkage file and shows its machine recomputed on each edit.

A front end beside the command line: nothing else in machdyn imports it, and it imports its web framework
(Starlette, uvicorn) only when the command starts it. See docs/studio.md.
"""

__all__ = ["app", "dragging", "fields", "server", "session"]
