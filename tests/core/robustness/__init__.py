"""The boundary tried as an adversary would, in child interpreters: fork, allocation failure,
threads racing on one array, Ctrl-C, random arguments."""
