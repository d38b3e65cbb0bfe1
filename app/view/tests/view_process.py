"""Starting and talking to `raystep view` for the tests of app/view/tests/."""

import json
import re
import signal
import struct
import subprocess
import time
import urllib.error
import urllib.request


class ViewProcess:
    """`raystep view ARGS --port PORT` as a child process; its address once it listens."""

    def __init__(self, program, arguments, port=0):
        self.process = subprocess.Popen(
            [program, "view", *arguments, "--port", str(port)],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.process.stdout.readline()
        match = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        if not match:
            self.process.kill()
            raise AssertionError("raystep view did not print its address: %r %r"
                                 % (line, self.process.stderr.read()))
        self.port = int(match.group(1))
        self.address = "http://127.0.0.1:%d" % self.port

    def request(self, path, api_header=True, host=None):
        """(status, content type, body bytes) of a GET."""
        request = urllib.request.Request(self.address + path)
        if api_header:
            request.add_header("X-Raystep", "1")
        if host:
            request.add_header("Host", host)
        try:
            with urllib.request.urlopen(request, timeout=60) as response:
                return response.status, response.headers.get("Content-Type"), response.read()
        except urllib.error.HTTPError as error:
            return error.code, error.headers.get("Content-Type"), error.read()

    def json(self, path):
        status, _, body = self.request(path)
        assert status == 200, "%s answered %d: %s" % (path, status, body[:300])
        return json.loads(body)

    def frame(self, path):
        """A binary frame: its JSON header and the pixels of each rectangle."""
        status, _, body = self.request(path)
        assert status == 200, "%s answered %d: %s" % (path, status, body[:300])
        length = struct.unpack("<I", body[:4])[0]
        header = json.loads(body[4:4 + length])
        offset = 4 + length
        pixels = []
        for x, y, w, h in header["tiles"]:
            pixels.append(((x, y, w, h), body[offset:offset + 4 * w * h]))
            offset += 4 * w * h
        assert offset == len(body), "the frame's size does not match its header"
        return header, pixels

    def wait_for_render(self, generation, timeout=120):
        """The render's pixels as one RGBA image once it is done: (header, bytes)."""
        deadline = time.time() + timeout
        image = None
        while time.time() < deadline:
            header, tiles = self.frame("/api/tiles?generation=%d&since=0" % generation)
            if header["state"] == "failed":
                raise AssertionError("the render failed: " + header["error"])
            if header["state"] == "done" and header["generation"] == generation:
                width, height = header["width"], header["height"]
                image = bytearray(4 * width * height)
                for (x, y, w, h), pixels in tiles:
                    for row in range(h):
                        start = 4 * ((y + row) * width + x)
                        image[start:start + 4 * w] = pixels[4 * w * row:4 * w * (row + 1)]
                return header, bytes(image)
            time.sleep(0.1)
        raise AssertionError("the render did not finish in %d s" % timeout)

    def interrupt(self, timeout=20):
        """Ctrl-C: (exit code, stdout, stderr)."""
        self.process.send_signal(signal.SIGINT)
        out, err = self.process.communicate(timeout=timeout)
        return self.process.returncode, out, err

    def kill(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.communicate()


def read_ppm(path):
    """(width, height, RGB bytes) of a binary PPM (P6, 8 bits)."""
    with open(path, "rb") as file:
        data = file.read()
    fields = []
    position = 0
    while len(fields) < 4:
        while data[position:position + 1].isspace():
            position += 1
        if data[position:position + 1] == b"#":
            position = data.index(b"\n", position) + 1
            continue
        end = position
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[position:end])
        position = end
    assert fields[0] == b"P6" and fields[3] == b"255", "not an 8-bit binary PPM"
    width, height = int(fields[1]), int(fields[2])
    return width, height, data[position + 1:position + 1 + 3 * width * height]


def rgb_of(rgba):
    return bytes(b for k, b in enumerate(rgba) if k % 4 != 3)

