"""The one exception type of the client: every refusal of the server, and every failure to reach
it, is a ClearskyError (docs/clients.md "Errors").

The server's refusals have one shape, {"error": {"code", "message", "parameter"}}
(docs/http-api.md "Errors"); the error keeps each member, the HTTP status and, for a 503 or 429,
the Retry-After the server sent."""

from __future__ import annotations

from typing import Any, Optional


class ClearskyError(Exception):
    """A request that did not succeed.

    Attributes:
        status: the HTTP status (400, 401, 404, 503, ...); None when no answer came (the server
            could not be reached, the connection broke, or a wait for an import or an
            evaluation ended without success).
        code: the API's stable error code (``invalid_parameter``, ``unauthorized``, ``busy``,
            ``no_database``, ...); for failures without an HTTP answer, ``connection_failed``,
            ``timeout``, or the code of a failed import or evaluation.
        message: the server's message, or a description of the failure.
        parameter: the parameter at fault (``turbidity``, ``views[3]``, ``Authorization``,
            ``role``), or None when no single parameter is.
        retry_after_s: the Retry-After of the last answer, s, or None.
        attempts: how many times the request was sent (more than 1 after retries).
        body: the parsed JSON of the answer (or of the failed import or ticket), when there was
            one.

    Example:
        >>> try:
        ...     client.radiance("preetham", 45, 0, sun_zenith=30, sun_azimuth=135, turbidity=99)
        ... except ClearskyError as error:
        ...     print(error.status, error.code, error.parameter)
        400 invalid_parameter turbidity
    """

    def __init__(self, status: Optional[int], code: str, message: str,
                 parameter: Optional[str] = None, *, retry_after_s: Optional[float] = None,
                 attempts: int = 1, body: Any = None) -> None:
        super().__init__(f"{status if status is not None else '-'} {code}: {message}")
        self.status = status
        self.code = code
        self.message = message
        self.parameter = parameter
        self.retry_after_s = retry_after_s
        self.attempts = attempts
        self.body = body
