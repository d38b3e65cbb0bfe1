#!/usr/bin/env python3
"""Runs a command and measures its whole process tree: peak memory, processor time, wall time.

    measure_process_tree.py REPORT.json -- COMMAND [ARGUMENT...]

Gradescope holds an autograder to 768 MB for the container, every process of it together; the
largest single process (GNU time's %M) says too little. Where it can, this puts the command in a
fresh memory cgroup and reads the cgroup's own peak, which counts every process and thread of the
tree, and the page cache they fill too (so it can only overstate what the tree needs):
  - cgroup v2: memory.peak (Linux 5.19 and later) of a child of this process's cgroup;
  - cgroup v1: memory.max_usage_in_bytes of a child in the memory hierarchy.
Where neither can be made (no cgroup file system, not root, a v2 cgroup whose controllers cannot
be delegated), it falls back to sampling: every 20 ms, the resident memory of each process of the
tree, summed (shared pages count once per process, which overstates); a spike shorter than a
sample can be missed, and the report says that this was the method.

Processor time: the cgroup's (v2 cpu.stat, v1 cpuacct.usage) where there is one, else the
children's rusage, which counts only the processes their parents waited for.

REPORT.json gets: exit_code, wall_seconds, cpu_seconds, cpu_method, peak_bytes, memory_method,
sampled_peak_bytes (the sampled figure, always there too) and samples. The command's exit code
is this program's.
"""

import json
import os
import resource
import subprocess
import sys
import threading
import time

SAMPLE_SECONDS = 0.02
PAGE_BYTES = os.sysconf("SC_PAGE_SIZE")


def own_cgroup(controller):
    """This process's cgroup path in the v1 hierarchy of `controller`, or in v2 for None."""
    with open("/proc/self/cgroup") as file:
        for line in file:
            _, controllers, path = line.rstrip("\n").split(":", 2)
            if controller is None and controllers == "":
                return path
            if controller is not None and controller in controllers.split(","):
                return path
    return None


def write(path, text):
    with open(path, "w") as file:
        file.write(text)


def read_number(path):
    with open(path) as file:
        return int(file.read().split()[0])


class Cgroup:
    """A child cgroup made for the run: where the command goes, and how to read it."""

    def __init__(self, folders, procs_files, peak, memory_method, cpu):
        self.folders = folders  # to remove afterwards, deepest first
        self.procs_files = procs_files  # each hierarchy's cgroup.procs to join
        self.peak = peak  # a function returning the peak bytes
        self.memory_method = memory_method
        self.cpu = cpu  # a function returning (seconds, method), or None

    def join(self):
        pid = str(os.getpid())
        for procs in self.procs_files:
            write(procs, pid)

    def pids(self):
        with open(self.procs_files[0]) as file:
            return [int(line) for line in file if line.strip()]

    def remove(self):
        for folder in self.folders:
            # The tree may take a moment to leave once its first process exits.
            for _ in range(50):
                try:
                    os.rmdir(folder)
                    break
                except OSError:
                    time.sleep(0.1)


def v2_parents():
    """Where a v2 child with the memory controller may go: below this process's own cgroup, or
    (for root, when its own cgroup holds processes and so cannot delegate) below the root."""
    path = own_cgroup(None)
    for mount in ("/sys/fs/cgroup", "/sys/fs/cgroup/unified"):
        controllers = os.path.join(mount, "cgroup.controllers")
        if path is None or not os.path.exists(controllers):
            continue
        with open(controllers) as file:
            if "memory" in file.read().split():
                yield mount + path.rstrip("/")
                yield mount


def v2_cgroup(name):
    for parent in v2_parents():
        child = os.path.join(parent, name)
        try:
            with open(os.path.join(parent, "cgroup.subtree_control")) as file:
                if "memory" not in file.read().split():
                    write(os.path.join(parent, "cgroup.subtree_control"), "+memory")
            os.mkdir(child)
        except OSError:
            continue
        if not os.path.exists(os.path.join(child, "memory.peak")):
            os.rmdir(child)
            continue

        def cpu():
            with open(os.path.join(child, "cpu.stat")) as file:
                for line in file:
                    key, value = line.split()
                    if key == "usage_usec":
                        return int(value) / 1e6, "cgroup v2 cpu.stat usage_usec"
            return None

        return Cgroup([child], [os.path.join(child, "cgroup.procs")],
                      lambda: read_number(os.path.join(child, "memory.peak")),
                      "cgroup v2 memory.peak (every process of the tree, page cache included)",
                      cpu)
    return None


def v1_cgroup(name):
    memory_path = own_cgroup("memory")
    memory_root = "/sys/fs/cgroup/memory"
    if memory_path is None or not os.path.isdir(memory_root):
        return None
    memory = os.path.join(memory_root + memory_path.rstrip("/"), name)
    try:
        os.mkdir(memory)
    except OSError:
        return None
    folders = [memory]
    procs = [os.path.join(memory, "cgroup.procs")]
    cpu = None
    cpuacct_path = own_cgroup("cpuacct")
    for root in ("/sys/fs/cgroup/cpuacct", "/sys/fs/cgroup/cpu,cpuacct"):
        if cpuacct_path is None or not os.path.isdir(root):
            continue
        cpuacct = os.path.join(root + cpuacct_path.rstrip("/"), name)
        try:
            os.mkdir(cpuacct)
        except OSError:
            continue
        folders.append(cpuacct)
        procs.append(os.path.join(cpuacct, "cgroup.procs"))

        def cpu(cpuacct=cpuacct):
            return read_number(os.path.join(cpuacct, "cpuacct.usage")) / 1e9, "cgroup v1 cpuacct.usage"

        break
    return Cgroup(folders, procs,
                  lambda: read_number(os.path.join(memory, "memory.max_usage_in_bytes")),
                  "cgroup v1 memory.max_usage_in_bytes (every process of the tree, page cache included)",
                  cpu)


def descendants(root):
    """The pids of `root` and every process below it, from /proc."""
    children = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as file:
                # The name, in parentheses, may hold spaces: the parent pid follows its close.
                parent = int(file.read().rsplit(")", 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue
        children.setdefault(parent, []).append(int(entry))
    found, stack = [], [root]
    while stack:
        pid = stack.pop()
        found.append(pid)
        stack.extend(children.get(pid, []))
    return found


def resident_bytes(pids):
    total = 0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/statm") as file:
                total += int(file.read().split()[1]) * PAGE_BYTES
        except (OSError, IndexError, ValueError):
            continue  # it ended between the listing and the read
    return total


def main(argv):
    if len(argv) < 4 or argv[2] != "--":
        print(f"usage: {argv[0]} REPORT.json -- COMMAND [ARGUMENT...]", file=sys.stderr)
        return 2
    report_path, command = argv[1], argv[3:]
    name = f"raystep-measure-{os.getpid()}"
    cgroup = v2_cgroup(name) or v1_cgroup(name)

    start = time.monotonic()
    try:
        process = subprocess.Popen(command, preexec_fn=cgroup.join if cgroup else None)
    except subprocess.SubprocessError:
        # The cgroup refused the process (a v2 parent with processes of its own, say): sample.
        cgroup.remove()
        cgroup = None
        process = subprocess.Popen(command)
    sampled_peak, samples = 0, 0
    done = threading.Event()

    def sample():
        nonlocal sampled_peak, samples
        while not done.is_set():
            pids = cgroup.pids() if cgroup else descendants(process.pid)
            sampled_peak = max(sampled_peak, resident_bytes(pids))
            samples += 1
            done.wait(SAMPLE_SECONDS)

    sampler = threading.Thread(target=sample)
    sampler.start()
    exit_code = process.wait()
    wall = time.monotonic() - start
    done.set()
    sampler.join()

    report = {"exit_code": exit_code, "wall_seconds": round(wall, 2),
              "sampled_peak_bytes": sampled_peak, "samples": samples}
    cpu = cgroup.cpu() if cgroup and cgroup.cpu else None
    if cpu is None:
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (usage.ru_utime + usage.ru_stime,
               "rusage of the children (only the processes their parents waited for)")
    report["cpu_seconds"], report["cpu_method"] = round(cpu[0], 2), cpu[1]
    if cgroup:
        report["peak_bytes"], report["memory_method"] = cgroup.peak(), cgroup.memory_method
        cgroup.remove()
    else:
        report["peak_bytes"] = sampled_peak
        report["memory_method"] = (f"resident memory of every process of the tree, summed, sampled "
                                   f"every {int(SAMPLE_SECONDS * 1000)} ms (no cgroup could be made "
                                   f"here; a shorter spike can be missed)")
    with open(report_path, "w") as file:
        json.dump(report, file, indent=1)
        file.write("\n")
    return exit_code


if __name__ == "__main__":
    sys.exit(main(sys.argv))
