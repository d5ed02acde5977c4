"""One HTTP exchange with the server, with the retries of RetryPolicy: the request is sent, the
answer's status, headers and body read (or streamed to a sink), and a refusal turned into a
ClearskyError (docs/clients.md).

Built on the standard library's http.client rather than urllib.request: an upload is streamed
from its file in blocks with a progress callback and a known Content-Length, a skydome is read in
chunks as the server computes it, and a write the server refuses before reading its body (401,
413: docs/http-api.md "From socket to handler and back") still yields the server's answer when
the connection is closed under the body being sent."""

from __future__ import annotations

import http.client
import json
import socket
import time
from dataclasses import dataclass
from typing import Any, Callable, Dict, Iterable, Mapping, Optional, Sequence, Tuple
from urllib.parse import quote, urlencode, urlsplit

from .errors import ClearskyError
from .retry import RetryNotice, RetryPolicy, parse_retry_after

QueryPairs = Sequence[Tuple[str, str]]
# Makes a fresh body for each attempt: (stream or bytes, Content-Length); None: no body.
BodyFactory = Callable[[], Tuple[Any, int]]

UPLOAD_BLOCK_BYTES = 1 << 16


@dataclass
class Answer:
    """A successful answer: status, headers (names lower-case) and body (empty when streamed)."""

    status: int
    headers: Dict[str, str]
    body: bytes

    def json(self) -> Any:
        return json.loads(self.body)


class Transport:
    """Sends requests to one server. Holds no connection between requests (each request opens
    its own), so one Transport may be used from several threads at once."""

    def __init__(self, base_url: str, token: Optional[str], timeout_s: float,
                 retry: RetryPolicy) -> None:
        parts = urlsplit(base_url)
        if parts.scheme not in ("http", "https") or not parts.hostname:
            raise ValueError(f"base_url must be http://host[:port][/prefix], not {base_url!r}")
        self._https = parts.scheme == "https"
        self._host = parts.hostname
        self._port = parts.port
        self._prefix = parts.path.rstrip("/")
        self._token = token
        self._timeout_s = timeout_s
        self._retry = retry

    def target(self, path: str, query: QueryPairs = ()) -> str:
        """The request target: the base URL's prefix, the path and the encoded query."""
        pairs = [(k, v) for k, v in query if v is not None]
        return self._prefix + path + ("?" + urlencode(pairs, quote_via=quote) if pairs else "")

    def request(self, method: str, path: str, query: QueryPairs = (), *,
                json_body: Any = None, body: Optional[BodyFactory] = None,
                content_type: Optional[str] = None, authorize: bool = False,
                sink: Optional[Callable[[bytes], None]] = None,
                chunk_bytes: int = 1 << 20) -> Answer:
        """Sends the request, retried by the policy; returns the 2xx answer or raises.

        json_body: a value sent as JSON; body: a factory of the body for uploads; authorize:
        send the bearer token (writes); sink: receives the body of a 2xx answer chunk by chunk
        (chunk_bytes at most) instead of it being kept in memory."""
        target = self.target(path, query)
        headers = {"Accept": "application/json, */*"}
        if authorize and self._token is not None:
            headers["Authorization"] = "Bearer " + self._token
        if json_body is not None:
            encoded = json.dumps(json_body).encode("utf-8")
            body = lambda: (encoded, len(encoded))  # noqa: E731
            content_type = "application/json"
        if content_type:
            headers["Content-Type"] = content_type
        attempt = 0
        waited_s = 0.0
        while True:
            attempt += 1
            status, answer_headers, raw = self._exchange(method, target, headers, body, sink,
                                                         chunk_bytes)
            if 200 <= status < 300:
                return Answer(status, answer_headers, raw)
            retry_after_s = parse_retry_after(answer_headers.get("retry-after"))
            error = error_from_answer(status, raw, retry_after_s, attempt)
            wait_s = self._retry.wait_before_retry(status, retry_after_s, attempt, waited_s)
            if wait_s is None:
                raise error
            if self._retry.on_retry is not None:
                self._retry.on_retry(RetryNotice(attempt, status, error.code, wait_s))
            time.sleep(wait_s)
            waited_s += wait_s

    def _connection(self) -> http.client.HTTPConnection:
        if self._https:
            return http.client.HTTPSConnection(self._host, self._port, timeout=self._timeout_s,
                                               blocksize=UPLOAD_BLOCK_BYTES)
        return http.client.HTTPConnection(self._host, self._port, timeout=self._timeout_s,
                                          blocksize=UPLOAD_BLOCK_BYTES)

    def _exchange(self, method: str, target: str, headers: Mapping[str, str],
                  body: Optional[BodyFactory], sink: Optional[Callable[[bytes], None]],
                  chunk_bytes: int) -> Tuple[int, Dict[str, str], bytes]:
        connection = self._connection()
        stream = None
        try:
            sent_headers = dict(headers)
            data: Any = None
            if body is not None:
                data, length = body()
                stream = data if hasattr(data, "read") else None
                sent_headers["Content-Length"] = str(length)
            elif method in ("POST", "PUT", "DELETE"):
                sent_headers["Content-Length"] = "0"
            try:
                connection.request(method, target, body=data, headers=sent_headers)
            except (BrokenPipeError, ConnectionResetError) as cut:
                # A write refused before its body was read (401, 413): the server answered and
                # closed while the body was still being sent; its answer may still be readable.
                try:
                    response = connection.getresponse()
                except (OSError, http.client.HTTPException):
                    raise connection_failed(self, cut) from cut
                return response.status, lower_headers(response.getheaders()), response.read()
            response = connection.getresponse()
            answer_headers = lower_headers(response.getheaders())
            if sink is not None and 200 <= response.status < 300:
                while True:
                    chunk = response.read(chunk_bytes)
                    if not chunk:
                        break
                    sink(chunk)
                return response.status, answer_headers, b""
            return response.status, answer_headers, response.read()
        except ClearskyError:
            raise
        except (OSError, http.client.HTTPException) as failure:
            raise connection_failed(self, failure) from failure
        finally:
            if stream is not None:
                stream.close()
            connection.close()


def lower_headers(pairs: Iterable[Tuple[str, str]]) -> Dict[str, str]:
    """Header names lower-cased (HTTP names are case-insensitive); repeated ones joined by
    commas (RFC 9110 section 5.3)."""
    headers: Dict[str, str] = {}
    for name, value in pairs:
        key = name.lower()
        headers[key] = headers[key] + ", " + value if key in headers else value
    return headers


def error_from_answer(status: int, raw: bytes, retry_after_s: Optional[float],
                      attempts: int) -> ClearskyError:
    """The ClearskyError of a refusal: the members of its {"error": {...}} body, or the status
    and the start of the text when the body is not the API's error (a proxy's page)."""
    try:
        parsed = json.loads(raw)
        detail = parsed["error"]
        return ClearskyError(status, str(detail.get("code", f"http_{status}")),
                             str(detail.get("message", "")), detail.get("parameter"),
                             retry_after_s=retry_after_s, attempts=attempts, body=parsed)
    except (ValueError, KeyError, TypeError, AttributeError):
        text = raw[:300].decode("utf-8", errors="replace")
        return ClearskyError(status, f"http_{status}", text, None, retry_after_s=retry_after_s,
                             attempts=attempts)


def connection_failed(transport: Transport, failure: BaseException) -> ClearskyError:
    kind = "timeout" if isinstance(failure, socket.timeout) else "connection_failed"
    where = f"{transport._host}:{transport._port or (443 if transport._https else 80)}"
    return ClearskyError(None, kind, f"{where}: {failure}")
