"""When and how long the client waits before sending a refused request again
(docs/clients.md "Retries").

The server answers 503 (tables being built, a full queue, the answer memory held by other
answers) and 429 (too many table builds from this client) with a Retry-After header when a later
attempt can succeed (docs/http-api.md "Errors"). Only those answers are retried, after exactly
the time the server asked, and within two bounds: a number of attempts and a total wait. A 503
without Retry-After (``no_database`` on a query replica) is raised at once: waiting would not
change it."""

from __future__ import annotations

import email.utils
from dataclasses import dataclass
from datetime import datetime, timezone
from typing import Callable, Optional

RETRIED_STATUSES = (429, 503)


@dataclass(frozen=True)
class RetryNotice:
    """What the client is about to wait for: passed to ``RetryPolicy.on_retry``.

    attempt: the attempt that was refused (1 for the first); status and code: its answer;
    wait_s: the time the client now sleeps (the server's Retry-After)."""

    attempt: int
    status: int
    code: str
    wait_s: float


@dataclass(frozen=True)
class RetryPolicy:
    """The bounds of the retries of one request.

    max_attempts: attempts in all, the first included (1: never retry).
    max_total_wait_s: the most the client sleeps for one request, all retries together; a
        Retry-After that would go beyond it is not waited for, the error is raised instead.
    on_retry: called before each wait (for logging or a progress display), or None.

    Example:
        >>> policy = RetryPolicy(max_attempts=3, max_total_wait_s=20,
        ...                      on_retry=lambda n: print("waiting", n.wait_s, "s:", n.code))
        >>> client = Client("http://127.0.0.1:8080", retry=policy)
    """

    max_attempts: int = 4
    max_total_wait_s: float = 30.0
    on_retry: Optional[Callable[[RetryNotice], None]] = None

    def __post_init__(self) -> None:
        if not self.max_attempts >= 1:
            raise ValueError("max_attempts must be at least 1")
        if not self.max_total_wait_s >= 0:
            raise ValueError("max_total_wait_s must be at least 0")

    def wait_before_retry(self, status: int, retry_after_s: Optional[float], attempt: int,
                          waited_s: float) -> Optional[float]:
        """The time to wait before attempt ``attempt + 1``, or None when the answer is final."""
        if status not in RETRIED_STATUSES or retry_after_s is None:
            return None
        if attempt >= self.max_attempts or waited_s + retry_after_s > self.max_total_wait_s:
            return None
        return retry_after_s


def parse_retry_after(value: Optional[str], now: Optional[datetime] = None) -> Optional[float]:
    """Retry-After as seconds: delay-seconds or an HTTP-date (RFC 9110 section 10.2.3); None when
    absent or unreadable."""
    if value is None:
        return None
    text = value.strip()
    if text.isdigit():
        return float(text)
    try:
        when = email.utils.parsedate_to_datetime(text)
    except (TypeError, ValueError):
        return None
    if when.tzinfo is None:
        when = when.replace(tzinfo=timezone.utc)
    return max(0.0, (when - (now or datetime.now(timezone.utc))).total_seconds())
