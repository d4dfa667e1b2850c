"""One loaded model blends many times, from one thread or several."""

import threading

import numpy as np

import tetblend


def test_a_thousand_blends_all_equal_the_first(bar_model):
    model = tetblend.load(str(bar_model))
    first = model.blend([0.3, 0.6])
    for _ in range(1000):
        assert np.array_equal(model.blend([0.3, 0.6]), first)


def test_threads_blend_one_model_at_once(bar_model):
    model = tetblend.load(str(bar_model))
    weights = [[0.1 * k, 0.5] for k in range(8)]
    expected = [model.blend(w) for w in weights]
    results = [None] * len(weights)

    def blend(k):
        results[k] = model.blend(weights[k])

    threads = [threading.Thread(target=blend, args=(k,)) for k in range(len(weights))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for got, want in zip(results, expected):
        assert np.array_equal(got, want)
